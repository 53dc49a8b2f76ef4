#include "obscura/io/stl_loader.h"

#include <cctype>
#include <cmath>
#include <cstring>
#include <optional>
#include <unordered_map>

#include "obscura/io/mesh_file.h"
#include "obscura/math/error.h"

namespace obscura {

namespace {

constexpr size_t kHeaderBytes = 84;  // 80-byte header + uint32 triangle count
constexpr size_t kTriangleBytes = 50;

// The material Assimp 5 gave every STL file.
Material stl_material() {
  Material m;
  m.name = "DefaultMaterial";
  PhongMaterial phong;
  phong.ambient = Rgb(0.05f);
  phong.diffuse = Rgb(1.f);
  phong.specular = Rgb(1.f);
  m.model = phong;
  return m;
}

// Shares vertices whose position and normal are bit-identical, as Assimp's vertex joining did.
class StlMeshBuilder {
 public:
  explicit StlMeshBuilder(std::string name) { mesh_.name = std::move(name); }

  void reserve(size_t triangles) {
    mesh_.indices.reserve(triangles * 3);
    lookup_.reserve(triangles / 2 + 1);
  }

  // `where` names the triangle in messages.
  void add_triangle(const float normal[3], const float corners[3][3], const std::string& where) {
    for (int c = 0; c < 3; ++c)
      for (int k = 0; k < 3; ++k)
        if (!std::isfinite(corners[c][k])) throw Error(where, "vertex is not finite");
    Vector3f n(normal[0], normal[1], normal[2]);
    float length = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
    if (!std::isfinite(length) || length == 0) {
      Vector3f e1(corners[1][0] - corners[0][0], corners[1][1] - corners[0][1],
                  corners[1][2] - corners[0][2]);
      Vector3f e2(corners[2][0] - corners[0][0], corners[2][1] - corners[0][1],
                  corners[2][2] - corners[0][2]);
      n = cross(e1, e2);
      length = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
      // A degenerate triangle covers no pixel; any unit normal will do.
      if (!std::isfinite(length) || length == 0) n = {0, 0, 1}, length = 1;
    }
    n = n / length;
    for (int c = 0; c < 3; ++c) mesh_.indices.push_back(vertex(corners[c], n));
  }

  Mesh finish() { return std::move(mesh_); }
  bool empty() const { return mesh_.indices.empty(); }

 private:
  struct Key {
    float v[6];
    bool operator==(const Key& o) const { return std::memcmp(v, o.v, sizeof v) == 0; }
  };
  struct KeyHash {
    size_t operator()(const Key& k) const {
      uint64_t h = 1469598103934665603ull;
      uint32_t bits[6];
      std::memcpy(bits, k.v, sizeof bits);
      for (uint32_t b : bits) h = (h ^ b) * 1099511628211ull;
      return size_t(h ^ (h >> 29));
    }
  };

  uint32_t vertex(const float p[3], const Vector3f& n) {
    Key key{{p[0], p[1], p[2], n.x, n.y, n.z}};
    for (float& f : key.v) f = f == 0 ? 0.f : f;  // -0 and +0 are one vertex
    auto [it, inserted] = lookup_.try_emplace(key, uint32_t(mesh_.positions.size()));
    if (inserted) {
      mesh_.positions.push_back({p[0], p[1], p[2]});
      mesh_.normals.push_back({n.x, n.y, n.z});
    }
    return it->second;
  }

  Mesh mesh_;
  std::unordered_map<Key, uint32_t, KeyHash> lookup_;
};

uint32_t read_u32_le(const char* p) {
  const auto* b = reinterpret_cast<const unsigned char*>(p);
  return uint32_t(b[0]) | uint32_t(b[1]) << 8 | uint32_t(b[2]) << 16 | uint32_t(b[3]) << 24;
}

float read_f32_le(const char* p) {
  uint32_t bits = read_u32_le(p);
  float f;
  std::memcpy(&f, &bits, 4);
  return f;
}

// Text: no NUL or other control bytes but whitespace in the first kilobyte.
bool looks_like_text(std::span<const char> bytes) {
  size_t n = std::min<size_t>(bytes.size(), 1024);
  for (size_t i = 0; i < n; ++i) {
    auto c = static_cast<unsigned char>(bytes[i]);
    if (c < 0x20 && c != '\n' && c != '\r' && c != '\t' && c != '\f' && c != '\v') return false;
  }
  return true;
}

bool starts_with_solid(std::span<const char> bytes) {
  size_t i = 0;
  while (i < bytes.size() &&
         (bytes[i] == ' ' || bytes[i] == '\t' || bytes[i] == '\r' || bytes[i] == '\n'))
    ++i;
  if (bytes.size() - i < 5) return false;
  for (size_t k = 0; k < 5; ++k)  // some writers capitalise: "SOLID"
    if (std::tolower(static_cast<unsigned char>(bytes[i + k])) != "solid"[k]) return false;
  return true;
}

Scene load_binary(std::span<const char> bytes, const std::string& name) {
  if (bytes.size() < kHeaderBytes)
    throw Error(name, "binary STL is " + std::to_string(bytes.size()) +
                          " bytes, shorter than its 84-byte header");
  uint64_t count = read_u32_le(bytes.data() + 80);
  uint64_t needed = kHeaderBytes + count * kTriangleBytes;
  if (needed > bytes.size())
    throw Error(name, "binary STL declares " + std::to_string(count) + " triangles, which need " +
                          std::to_string(needed) + " bytes, but the file has " +
                          std::to_string(bytes.size()) + " (truncated?)");
  StlMeshBuilder builder("mesh 0");
  builder.reserve(count);
  for (uint64_t t = 0; t < count; ++t) {
    const char* p = bytes.data() + kHeaderBytes + t * kTriangleBytes;
    float normal[3], corners[3][3];
    for (int k = 0; k < 3; ++k) normal[k] = read_f32_le(p + 4 * k);
    for (int c = 0; c < 3; ++c)
      for (int k = 0; k < 3; ++k) corners[c][k] = read_f32_le(p + 12 + 12 * c + 4 * k);
    builder.add_triangle(normal, corners, name + ": triangle " + std::to_string(t));
  }
  return single_mesh_scene(name, builder.finish(), stl_material());
}

// solid NAME / facet normal X Y Z / outer loop / vertex X Y Z (×3) / endloop / endfacet /
// endsolid NAME; one statement per line, keywords case-insensitive as some writers capitalise.
class AsciiStlReader {
 public:
  AsciiStlReader(std::span<const char> bytes, const std::string& name)
      : lines_{std::string_view(bytes.data(), bytes.size())}, name_(name) {}

  Scene read() {
    std::string_view line;
    while (lines_.next(line)) {
      TextCursor c{line.data(), line.data() + line.size()};
      std::string keyword = lower(c.token());
      if (keyword.empty()) continue;
      if (keyword == "solid") {
        expect(state_ == State::kOutside, "'solid' inside another solid");
        std::string_view solid_name = c.rest();
        builder_.emplace(solid_name.empty() ? "mesh " + std::to_string(meshes_.size())
                                            : std::string(solid_name));
        state_ = State::kSolid;
      } else if (keyword == "facet") {
        expect(state_ == State::kSolid, "'facet' outside a solid or inside another facet");
        expect(lower(c.token()) == "normal", "expected 'facet normal X Y Z'");
        for (float& n : normal_) expect(c.number(n), "expected 'facet normal X Y Z'");
        state_ = State::kFacet;
      } else if (keyword == "outer") {
        expect(state_ == State::kFacet && lower(c.token()) == "loop",
               "expected 'outer loop' right after 'facet normal'");
        state_ = State::kLoop;
        corners_ = 0;
      } else if (keyword == "vertex") {
        expect(state_ == State::kLoop, "'vertex' outside 'outer loop'");
        expect(corners_ < 3, "a facet with more than 3 vertices");
        for (float& v : corner_[corners_]) expect(c.number(v), "expected 'vertex X Y Z'");
        ++corners_;
      } else if (keyword == "endloop") {
        expect(state_ == State::kLoop && corners_ == 3, "'endloop' after other than 3 vertices");
        state_ = State::kEndLoop;
      } else if (keyword == "endfacet") {
        expect(state_ == State::kEndLoop, "'endfacet' without 'outer loop … endloop'");
        builder_->add_triangle(normal_, corner_, where());
        state_ = State::kSolid;
      } else if (keyword == "endsolid") {
        expect(state_ == State::kSolid, "'endsolid' inside a facet");
        if (!builder_->empty()) meshes_.push_back(builder_->finish());
        builder_.reset();
        state_ = State::kOutside;
      } else {
        expect(false, "unknown keyword '" + std::string(keyword.substr(0, 40)) + "'");
      }
    }
    if (state_ != State::kOutside) throw Error(name_, "file ends before 'endsolid' (truncated?)");
    Scene scene;
    scene.name = scene_name_of(name_);
    scene.materials.push_back(stl_material());
    for (Mesh& mesh : meshes_) {
      scene.add_mesh(std::move(mesh));
      scene.instances.back().material = 0;  // as the Assimp loader set it
    }
    return scene;
  }

 private:
  enum class State { kOutside, kSolid, kFacet, kLoop, kEndLoop };

  static std::string lower(std::string_view s) {
    std::string out(s);
    for (char& ch : out) ch = char(std::tolower(static_cast<unsigned char>(ch)));
    return out;
  }
  std::string where() const { return name_ + ":" + std::to_string(lines_.line_number); }
  void expect(bool ok, const std::string& message) const {
    if (!ok) throw Error(where(), message);
  }

  LineReader lines_;
  const std::string& name_;
  State state_ = State::kOutside;
  std::optional<StlMeshBuilder> builder_;
  std::vector<Mesh> meshes_;
  float normal_[3] = {};
  float corner_[3][3] = {};
  int corners_ = 0;
};

}  // namespace

Scene load_stl_bytes(std::span<const char> bytes, const std::string& name) {
  if (bytes.empty()) throw Error(name, "file is empty");
  bool size_matches_count =
      bytes.size() >= kHeaderBytes &&
      kHeaderBytes + uint64_t(read_u32_le(bytes.data() + 80)) * kTriangleBytes == bytes.size();
  if (!size_matches_count && starts_with_solid(bytes) && looks_like_text(bytes))
    return AsciiStlReader(bytes, name).read();
  return load_binary(bytes, name);
}

Scene load_stl(const std::string& path) {
  std::vector<char> bytes = read_mesh_file(path);
  return load_stl_bytes(bytes, path);
}

}  // namespace obscura
