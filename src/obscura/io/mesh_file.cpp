#include "obscura/io/mesh_file.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "obscura/io/input_file.h"
#include "obscura/math/error.h"

namespace obscura {

uint64_t check_mesh_file(const std::string& path) {
  return check_input_file(path, kMaxMeshFileBytes, "mesh files");
}

std::vector<char> read_mesh_file(const std::string& path) {
  uint64_t size = check_mesh_file(path);
  std::vector<char> bytes(size);
  if (size == 0) return bytes;
  std::ifstream in(path, std::ios::binary);
  if (!in || !in.read(bytes.data(), std::streamsize(size)) || in.gcount() != std::streamsize(size))
    throw Error(path, "cannot read the whole file");
  return bytes;
}

std::string_view TextCursor::token() {
  skip_blanks();
  const char* start = p;
  while (p < end && *p != ' ' && *p != '\t' && *p != '\r') ++p;
  return {start, size_t(p - start)};
}

std::string_view TextCursor::rest() {
  skip_blanks();
  const char* last = end;
  while (last > p && (last[-1] == ' ' || last[-1] == '\t' || last[-1] == '\r')) --last;
  std::string_view out(p, size_t(last - p));
  p = end;
  return out;
}

namespace {

template <typename T>
bool parse_number(TextCursor& c, T& out) {
  c.skip_blanks();
  const char* start = c.p;
  // from_chars takes no leading '+', which OBJ and PLY writers do emit.
  if (start < c.end && *start == '+' && start + 1 < c.end && start[1] != '-') ++start;
  T value{};
  auto [next, ec] = std::from_chars(start, c.end, value);
  if (ec != std::errc() || (next < c.end && *next != ' ' && *next != '\t' && *next != '\r'))
    return false;
  out = value;
  c.p = next;
  return true;
}

}  // namespace

bool TextCursor::number(float& out) {
  // Out-of-range values ("1e99") are an error for from_chars; parse wide and narrow, so that they
  // become infinities and the finiteness checks name them.
  double wide = 0;
  if (!number(wide)) return false;
  out = float(wide);
  return true;
}

bool TextCursor::number(double& out) {
  return parse_number(*this, out);
}

bool TextCursor::integer(int64_t& out) {
  return parse_number(*this, out);
}

bool LineReader::next(std::string_view& line) {
  if (offset >= text.size()) return false;
  size_t newline = text.find('\n', offset);
  if (newline == std::string_view::npos) newline = text.size();
  line = text.substr(offset, newline - offset);
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  offset = newline + 1;
  ++line_number;
  return true;
}

std::string scene_name_of(const std::string& path) {
  return std::filesystem::path(path).stem().string();
}

Scene single_mesh_scene(const std::string& path, Mesh mesh, Material material) {
  Scene scene;
  scene.name = scene_name_of(path);
  scene.materials.push_back(std::move(material));
  mesh.material = 0;
  // A mesh with no triangle gets no instance, as a node without a drawable mesh had none.
  if (mesh.indices.empty()) {
    scene.meshes.push_back(std::move(mesh));
    return scene;
  }
  scene.add_mesh(std::move(mesh));
  scene.instances.back().material = 0;  // as the Assimp loader set it
  return scene;
}

namespace {

// The angle at `at` between the directions to `a` and `b`; NaN when either has no length.
double angle_between(const Point3f& at, const Point3f& a, const Point3f& b) {
  Vector3d u(a.x - at.x, a.y - at.y, a.z - at.z), v(b.x - at.x, b.y - at.y, b.z - at.z);
  double cosine = dot(u, v) / std::sqrt(dot(u, u) * dot(v, v));
  return std::acos(std::clamp(cosine, -1.0, 1.0));
}

}  // namespace

bool triangulate_polygon(std::span<const uint32_t> corners, const std::vector<Point3f>& positions,
                         std::vector<uint32_t>& indices) {
  if (corners.size() < 3) return true;
  if (indices.size() / 3 + (corners.size() - 2) > kMaxMeshTriangles) return false;
  size_t start = 0;
  if (corners.size() == 4 && !positions.empty()) {
    // Corner i is reflex when the two angles its diagonal to corner i + 2 makes with its edges
    // add up to more than a half turn: the diagonal then leaves the quad.
    for (size_t i = 0; i < 4; ++i) {
      const Point3f& v = positions[corners[i]];
      const Point3f& opposite = positions[corners[(i + 2) % 4]];
      double sum = angle_between(v, positions[corners[(i + 3) % 4]], opposite) +
                   angle_between(v, positions[corners[(i + 1) % 4]], opposite);
      if (sum > std::numbers::pi) {
        start = i;
        break;
      }
    }
  }
  size_t n = corners.size();
  for (size_t k = 2; k < n; ++k)
    indices.insert(indices.end(),
                   {corners[start], corners[(start + k - 1) % n], corners[(start + k) % n]});
  return true;
}

void drop_unused_vertices(Mesh& mesh) {
  std::vector<uint8_t> used(mesh.positions.size(), 0);
  for (uint32_t index : mesh.indices) used[index] = 1;
  // New numbers in the file's order.
  std::vector<uint32_t> remap(mesh.positions.size());
  uint32_t kept = 0;
  for (size_t i = 0; i < used.size(); ++i) remap[i] = used[i] ? kept++ : 0;
  if (kept == mesh.positions.size()) return;
  for (uint32_t& index : mesh.indices) index = remap[index];
  auto compact = [&](auto& attribute) {
    if (attribute.empty()) return;
    for (size_t i = 0; i < used.size(); ++i)
      if (used[i]) attribute[remap[i]] = attribute[i];  // remap[i] <= i: in place
    attribute.resize(kept);
    attribute.shrink_to_fit();
  };
  compact(mesh.positions);
  compact(mesh.normals);
  compact(mesh.uvs);
  compact(mesh.uvs1);
  compact(mesh.tangents);
  compact(mesh.colors);
  compact(mesh.color_alphas);
}

}  // namespace obscura
