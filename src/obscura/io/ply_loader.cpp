#include "obscura/io/ply_loader.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "obscura/io/mesh_file.h"
#include "obscura/io/ply_header.h"
#include "obscura/math/error.h"

namespace obscura {

namespace {

// Reads values from a binary body. Returns false at the end of the bytes.
class BinarySource {
 public:
  BinarySource(std::span<const char> bytes, size_t offset, bool big_endian)
      : p_(bytes.data() + offset), end_(bytes.data() + bytes.size()), swap_(big_endian) {}

  bool value(PlyType type, double& out) {
    size_t size = ply_type_size(type);
    if (size_t(end_ - p_) < size) return false;
    unsigned char b[8];
    std::memcpy(b, p_, size);
    p_ += size;
    if (swap_) std::reverse(b, b + size);
    switch (type) {
      case PlyType::kInt8:
        out = int8_t(b[0]);
        break;
      case PlyType::kUint8:
        out = b[0];
        break;
      case PlyType::kInt16:
        out = load<int16_t>(b);
        break;
      case PlyType::kUint16:
        out = load<uint16_t>(b);
        break;
      case PlyType::kInt32:
        out = load<int32_t>(b);
        break;
      case PlyType::kUint32:
        out = load<uint32_t>(b);
        break;
      case PlyType::kFloat32:
        out = load<float>(b);
        break;
      case PlyType::kFloat64:
        out = load<double>(b);
        break;
    }
    return true;
  }
  // Where reading stopped, for messages.
  std::string position(const std::string& name, const char* begin) const {
    return name + ": byte " + std::to_string(p_ - begin);
  }

 private:
  template <typename T>
  static T load(const unsigned char* b) {
    T v;
    std::memcpy(&v, b, sizeof v);
    return v;
  }
  const char* p_;
  const char* end_;
  bool swap_;
};

// Reads whitespace-separated numbers from an ASCII body, counting lines for messages.
class AsciiSource {
 public:
  AsciiSource(std::span<const char> bytes, size_t offset, size_t header_lines)
      : p_(bytes.data() + offset), end_(bytes.data() + bytes.size()), line_(header_lines + 1) {}

  // False at the end of the text; throws (through `malformed`) for a token that is no number.
  bool value(PlyType, double& out) {
    while (p_ < end_ && (*p_ == ' ' || *p_ == '\t' || *p_ == '\r' || *p_ == '\n')) {
      if (*p_ == '\n') ++line_;
      ++p_;
    }
    if (p_ >= end_) return false;
    const char* start = p_;
    if (*start == '+' && start + 1 < end_) ++start;
    auto [next, ec] = std::from_chars(start, end_, out);
    bool separated =
        next >= end_ || *next == ' ' || *next == '\t' || *next == '\r' || *next == '\n';
    if (next == start || !separated || (ec != std::errc() && ec != std::errc::result_out_of_range))
      malformed_ = true;
    else if (ec == std::errc::result_out_of_range)
      out = std::numeric_limits<double>::infinity();  // caught by the finiteness checks
    p_ = next == start ? p_ + 1 : next;
    return true;
  }
  bool malformed() const { return malformed_; }
  std::string position(const std::string& name, const char*) const {
    return name + ":" + std::to_string(line_);
  }

 private:
  const char* p_;
  const char* end_;
  size_t line_;
  bool malformed_ = false;
};

// What a vertex property feeds.
enum class Role : uint8_t { kSkip, kX, kY, kZ, kNx, kNy, kNz, kU, kV, kRed, kGreen, kBlue };

struct VertexLayout {
  std::vector<Role> roles;  // per property
  bool normals = false, uvs = false, colors = false;
  double color_scale[3] = {1, 1, 1};
};

VertexLayout vertex_layout(const PlyElement& e, const std::string& name) {
  VertexLayout layout;
  layout.roles.assign(e.properties.size(), Role::kSkip);
  auto assign = [&](std::initializer_list<const char*> names, std::initializer_list<Role> roles) {
    std::vector<int> found;
    for (const char* n : names) found.push_back(e.find(n));
    for (int f : found)
      if (f < 0 || e.properties[f].is_list) return false;
    auto role = roles.begin();
    for (int f : found) layout.roles[f] = *role++;
    return true;
  };
  if (!assign({"x", "y", "z"}, {Role::kX, Role::kY, Role::kZ}))
    throw Error(name, "element 'vertex' lacks one of the scalar properties x, y, z");
  layout.normals = assign({"nx", "ny", "nz"}, {Role::kNx, Role::kNy, Role::kNz});
  for (auto [u, v] : {std::pair{"u", "v"}, std::pair{"s", "t"}, std::pair{"texture_u", "texture_v"},
                      std::pair{"texture_s", "texture_t"}})
    if (!layout.uvs) layout.uvs = assign({u, v}, {Role::kU, Role::kV});
  layout.colors = assign({"red", "green", "blue"}, {Role::kRed, Role::kGreen, Role::kBlue});
  if (layout.colors) {
    const char* channels[] = {"red", "green", "blue"};
    for (int c = 0; c < 3; ++c)
      layout.color_scale[c] = ply_type_max(e.properties[e.find(channels[c])].type);
  }
  return layout;
}

const std::vector<Point3f> kNoPositions;

template <typename Source>
class PlyBodyReader {
 public:
  PlyBodyReader(Source& source, const PlyHeader& header, std::span<const char> bytes,
                const std::string& name, std::vector<std::string>& warnings)
      : source_(source), header_(header), bytes_(bytes), name_(name), warnings_(warnings) {}

  Mesh read() {
    const PlyElement* vertices = nullptr;
    for (const PlyElement& e : header_.elements)
      if (e.name == "vertex") {
        if (vertices) throw Error(name_, "two 'vertex' elements");
        vertices = &e;
      }
    if (!vertices) throw Error(name_, "no 'vertex' element");
    vertex_count_ = vertices->count;
    for (const PlyElement& e : header_.elements) {
      if (&e == vertices)
        read_vertices(e);
      else if (e.name == "face")
        read_faces(e);
      else
        skip(e);
    }
    return std::move(mesh_);
  }

 private:
  [[noreturn]] void fail(const PlyElement& e, uint64_t entry, const std::string& message) {
    throw Error(source_.position(name_, bytes_.data()),
                "element '" + e.name + "' entry " + std::to_string(entry) + " of " +
                    std::to_string(e.count) + ": " + message);
  }

  double next(const PlyElement& e, uint64_t entry, PlyType type) {
    double v = 0;
    if (!source_.value(type, v)) fail(e, entry, "the file ends here (truncated)");
    if constexpr (std::is_same_v<Source, AsciiSource>)
      if (source_.malformed()) fail(e, entry, "expected a number");
    return v;
  }

  // A list length or index: an integer within [0, limit].
  uint64_t next_integer(const PlyElement& e, uint64_t entry, PlyType type, double limit,
                        const char* what) {
    double v = next(e, entry, type);
    if (!(v >= 0 && v <= limit) || v != std::floor(v))
      fail(e, entry,
           std::string(what) + " " + std::to_string(v) + " is not an integer in [0, " +
               std::to_string(uint64_t(limit)) + "]");
    return uint64_t(v);
  }

  void skip_list(const PlyElement& e, uint64_t entry, const PlyProperty& p) {
    uint64_t n = next_integer(e, entry, p.count_type, 4294967295.0, "list length");
    for (uint64_t i = 0; i < n; ++i) next(e, entry, p.type);
  }

  void read_vertices(const PlyElement& e) {
    VertexLayout layout = vertex_layout(e, name_);
    mesh_.positions.resize(e.count);
    if (layout.normals) mesh_.normals.resize(e.count);
    if (layout.uvs) mesh_.uvs.resize(e.count);
    if (layout.colors) mesh_.colors.resize(e.count);
    double v[12] = {};
    for (uint64_t i = 0; i < e.count; ++i) {
      for (size_t k = 0; k < e.properties.size(); ++k) {
        if (e.properties[k].is_list)
          skip_list(e, i, e.properties[k]);
        else
          v[size_t(layout.roles[k])] = next(e, i, e.properties[k].type);
      }
      auto at = [&](Role r) { return float(v[size_t(r)]); };
      Point3f p(at(Role::kX), at(Role::kY), at(Role::kZ));
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
        fail(e, i, "position is not finite");
      mesh_.positions[i] = p;
      if (layout.normals)
        mesh_.normals[i] = unit_normal(at(Role::kNx), at(Role::kNy), at(Role::kNz));
      if (layout.uvs) mesh_.uvs[i] = {at(Role::kU), 1 - at(Role::kV)};
      if (layout.colors)
        mesh_.colors[i] = {float(v[size_t(Role::kRed)] / layout.color_scale[0]),
                           float(v[size_t(Role::kGreen)] / layout.color_scale[1]),
                           float(v[size_t(Role::kBlue)] / layout.color_scale[2])};
    }
  }

  // Scanners write unnormalised or zero normals; a zero one keeps +z rather than NaN.
  static Normal3f unit_normal(float x, float y, float z) {
    float length = std::sqrt(x * x + y * y + z * z);
    if (!(length > 0) || !std::isfinite(length)) return {0, 0, 1};
    return {x / length, y / length, z / length};
  }

  void read_faces(const PlyElement& e) {
    int list = e.find("vertex_indices");
    if (list < 0) list = e.find("vertex_index");
    if (list < 0 || !e.properties[list].is_list)
      throw Error(name_, "element 'face' has no list property 'vertex_indices' or 'vertex_index'");
    // A hint only, bounded by what the bytes can hold: a triangle takes at least its list
    // length and three indices ("3 0 1 2\n" in ASCII).
    const PlyProperty& p = e.properties[list];
    uint64_t triangle_bytes = header_.format == PlyFormat::kAscii
                                  ? 8
                                  : ply_type_size(p.count_type) + 3 * ply_type_size(p.type);
    mesh_.indices.reserve(mesh_.indices.size() +
                          3 * std::min<uint64_t>(e.count, bytes_.size() / triangle_bytes));
    double last_vertex = double(vertex_count_) - 1;
    for (uint64_t f = 0; f < e.count; ++f) {
      for (size_t k = 0; k < e.properties.size(); ++k) {
        const PlyProperty& p = e.properties[k];
        if (int(k) != list) {
          p.is_list ? skip_list(e, f, p) : void(next(e, f, p.type));
          continue;
        }
        uint64_t n = next_integer(e, f, p.count_type, 4294967295.0, "list length");
        corners_.clear();
        for (uint64_t c = 0; c < n; ++c) {
          double index = next(e, f, p.type);
          if (!(index >= 0 && index <= last_vertex) || index != std::floor(index)) {
            // As the file wrote it: an index may be 1e30 or NaN, which no integer holds.
            char shown[32];
            std::snprintf(shown, sizeof shown, "%.17g", index);
            fail(e, f,
                 std::string("refers to vertex ") + shown + ", past the vertex count " +
                     std::to_string(vertex_count_));
          }
          corners_.push_back(uint32_t(index));
        }
        // Faces before the vertices (allowed, never seen) are fanned: no positions to test.
        bool have_positions = mesh_.positions.size() == vertex_count_;
        if (!triangulate_polygon(corners_, have_positions ? mesh_.positions : kNoPositions,
                                 mesh_.indices))
          fail(e, f,
               "more than " + std::to_string(kMaxMeshTriangles) +
                   " triangles, the most one mesh may have");
      }
    }
  }

  void skip(const PlyElement& e) {
    if (e.name == "tristrips" && e.count > 0)
      warnings_.push_back(name_ + ": element 'tristrips' is not read; only 'face' lists are");
    for (uint64_t i = 0; i < e.count; ++i)
      for (const PlyProperty& p : e.properties)
        p.is_list ? skip_list(e, i, p) : void(next(e, i, p.type));
  }

  Source& source_;
  const PlyHeader& header_;
  std::span<const char> bytes_;
  const std::string& name_;
  std::vector<std::string>& warnings_;
  uint64_t vertex_count_ = 0;
  std::vector<uint32_t> corners_;
  Mesh mesh_;
};

// Assimp's PLY material.
Material ply_material() {
  Material m;
  m.name = "material 0";
  PhongMaterial phong;
  phong.ambient = phong.diffuse = phong.specular = Rgb(1.f);
  m.model = phong;
  return m;
}

}  // namespace

Scene load_ply_bytes(std::span<const char> bytes, const std::string& name) {
  PlyHeader header = parse_ply_header(bytes, name);
  std::vector<std::string> warnings;
  Mesh mesh;
  if (header.format == PlyFormat::kAscii) {
    AsciiSource source(bytes, header.data_offset, header.lines);
    mesh = PlyBodyReader<AsciiSource>(source, header, bytes, name, warnings).read();
  } else {
    BinarySource source(bytes, header.data_offset, header.format == PlyFormat::kBinaryBigEndian);
    mesh = PlyBodyReader<BinarySource>(source, header, bytes, name, warnings).read();
  }
  drop_unused_vertices(mesh);
  mesh.name = "mesh 0";
  Scene scene = single_mesh_scene(name, std::move(mesh), ply_material());
  scene.warnings = std::move(warnings);
  return scene;
}

Scene load_ply(const std::string& path) {
  std::vector<char> bytes = read_mesh_file(path);
  return load_ply_bytes(bytes, path);
}

}  // namespace obscura
