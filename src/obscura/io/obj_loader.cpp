#include "obscura/io/obj_loader.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <map>

#include "obscura/io/file_lines.h"
#include "obscura/io/flat_index_map.h"
#include "obscura/io/mesh_file.h"
#include "obscura/io/mtl_reader.h"
#include "obscura/io/texture_loader.h"
#include "obscura/math/error.h"

namespace obscura {

namespace {

constexpr int32_t kNone = -1;  // a corner without vt or vn

struct MeshBuild {
  Mesh mesh;
  std::string object;    // the instance's name
  std::string material;  // "" = DefaultMaterial
  // Each distinct (v, vt, vn) the faces use → its vertex. The indices are canonical: the first
  // of the v (vt, vn) lines with the same values, so that a position written twice in the file
  // is one vertex, as Assimp's vertex joining made it.
  FlatIndexMap<3> corners;
  std::vector<uint8_t> has_normal;  // per vertex
  uint32_t serial = 0;              // which mesh this is, for ObjReader::last_use_
};

// `Lines` is LineReader (bytes in memory) or FileLines (a file streamed in chunks).
template <typename Lines>
class ObjReader {
 public:
  ObjReader(Lines& lines, const std::string& name, const std::string& base_dir)
      : lines_(lines), name_(name), base_dir_(base_dir) {}

  Scene read() {
    std::string_view line;
    while (lines_.next(line)) {
      TextCursor c{line.data(), line.data() + line.size()};
      std::string_view keyword = c.token();
      if (keyword.empty() || keyword[0] == '#') continue;
      if (keyword == "v") {
        vertex_position(c);
      } else if (keyword == "vt") {
        float uv[2] = {0, 0};
        if (!c.number(uv[0])) fail("expected 'vt U [V [W]]'");
        c.number(uv[1]);
        finite(uv[0]) && finite(uv[1]) ? void() : fail("texture coordinate is not finite");
        uvs_.push_back({uv[0], 1 - uv[1]});  // glTF's convention: v = 0 at the image's top
        canonical_vt_.push_back(int32_t(
            uv_index_
                .find_or_add(FlatIndexMap<2>::float_key(uv[0], uv[1]), uint32_t(uvs_.size() - 1))
                .first));
      } else if (keyword == "vn") {
        float n[3];
        for (float& x : n)
          if (!c.number(x)) fail("expected 'vn X Y Z'");
        if (!finite(n[0]) || !finite(n[1]) || !finite(n[2])) fail("normal is not finite");
        normals_.push_back({n[0], n[1], n[2]});
        canonical_vn_.push_back(
            int32_t(normal_index_
                        .find_or_add(FlatIndexMap<3>::float_key(n[0], n[1], n[2]),
                                     uint32_t(normals_.size() - 1))
                        .first));
      } else if (keyword == "f") {
        face(c);
      } else if (keyword == "o" || keyword == "g") {
        std::string object(c.rest());
        // An unnamed "o"/"g", or a "g" naming the current object, keeps the current object.
        if (!object.empty() && !(keyword == "g" && current() && current()->object == object))
          start_object(object);
      } else if (keyword == "usemtl") {
        use_material(std::string(c.rest()));
      } else if (keyword == "mtllib") {
        material_library(std::string(c.rest()));
      }
      // s, l, p, vp, curves and anything else: not geometry this loader renders.
    }
    return finish();
  }

 private:
  [[noreturn]] void fail(const std::string& message) const {
    throw Error(name_ + ":" + std::to_string(lines_.line_number), message);
  }
  static bool finite(float x) { return std::isfinite(x); }

  void vertex_position(TextCursor& c) {
    float p[3];
    for (float& x : p)
      if (!c.number(x)) fail("expected 'v X Y Z'");
    if (!finite(p[0]) || !finite(p[1]) || !finite(p[2])) fail("vertex position is not finite");
    positions_.push_back({p[0], p[1], p[2]});
    last_use_.emplace_back();
    float extra[4];
    int count = 0;
    while (count < 4 && c.number(extra[count])) ++count;
    Rgb color(1.f);
    if (count == 3) {  // "v x y z r g b"; a lone fourth value is the rational weight w
      if (colors_.size() < positions_.size() - 1) colors_.resize(positions_.size() - 1, Rgb(1.f));
      color = {extra[0], extra[1], extra[2]};
      colors_.push_back(color);
    }
    auto key = FlatIndexMap<6>::float_key(p[0], p[1], p[2], color.r, color.g, color.b);
    canonical_v_.push_back(
        int32_t(position_index_.find_or_add(key, uint32_t(positions_.size() - 1)).first));
  }

  MeshBuild* current() { return objects_.empty() ? nullptr : &objects_.back().back(); }

  void start_object(const std::string& object) {
    objects_.emplace_back().emplace_back().serial = mesh_count_++;
    MeshBuild& m = objects_.back().back();
    m.mesh.name = m.object = object;
    m.material = material_;
  }

  void use_material(const std::string& material) {
    if (material.empty() || material == material_) return;
    material_ = material;
    if (!current()) start_object("defaultobject");
    if (current()->mesh.indices.empty()) {
      current()->material = material;
      return;
    }
    std::vector<MeshBuild>& object = objects_.back();
    MeshBuild& next = object.emplace_back();
    next.serial = mesh_count_++;
    next.object = object.front().object;
    next.mesh.name = next.material = material;
  }

  // Resolves a 1-based or negative (relative) OBJ index into `count` elements, naming `what`.
  int32_t resolve(std::string_view text, size_t count, const char* what) {
    int64_t i = 0;
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), i);
    if (ec != std::errc() || end != text.data() + text.size())
      fail("malformed face corner index '" + std::string(text.substr(0, 40)) + "'");
    int64_t index = i > 0 ? i - 1 : int64_t(count) + i;
    if (i == 0 || index < 0 || index >= int64_t(count))
      fail(std::string("face refers to ") + what + " " + std::to_string(i) + ", but " +
           std::to_string(count) + " " + what + (count == 1 ? " is" : "s are") +
           " defined before this line");
    return int32_t(index);
  }

  void face(TextCursor& c) {
    corners_.clear();
    for (std::string_view token = c.token(); !token.empty(); token = c.token()) {
      size_t slash1 = token.find('/');
      std::string_view v = token.substr(0, slash1), vt, vn;
      if (slash1 != std::string_view::npos) {
        std::string_view rest = token.substr(slash1 + 1);
        size_t slash2 = rest.find('/');
        vt = rest.substr(0, slash2);
        if (slash2 != std::string_view::npos) vn = rest.substr(slash2 + 1);
      }
      Corner corner{resolve(v, positions_.size(), "vertex"),
                    vt.empty() ? kNone : resolve(vt, uvs_.size(), "texture coordinate"),
                    vn.empty() ? kNone : resolve(vn, normals_.size(), "normal")};
      corners_.push_back(corner);
    }
    if (corners_.size() < 3) return;  // a point or a line: not rendered
    if (!current()) start_object("defaultobject");
    MeshBuild& m = *current();
    // Every corner's vertex first, in corner order (the order Assimp numbered them in).
    polygon_.clear();
    for (const Corner& corner : corners_) polygon_.push_back(vertex(m, corner));
    if (!triangulate_polygon(polygon_, m.mesh.positions, m.mesh.indices))
      fail("mesh '" + m.mesh.name + "' would have more than " + std::to_string(kMaxMeshTriangles) +
           " triangles, the most one mesh may have");
  }

  struct Corner {
    int32_t v, vt, vn;
  };

  uint32_t vertex(MeshBuild& m, const Corner& corner) {
    auto v = uint32_t(canonical_v_[corner.v]);
    int32_t vt = corner.vt == kNone ? kNone : canonical_vt_[corner.vt];
    int32_t vn = corner.vn == kNone ? kNone : canonical_vn_[corner.vn];
    // Neighbouring faces share corners: most lookups are answered here, in file order, without
    // the random access of the hash table.
    LastUse& last = last_use_[v];
    if (last.mesh == m.serial && last.vt == vt && last.vn == vn) return last.vertex;
    auto next = uint32_t(m.mesh.positions.size());
    auto [index, added] = m.corners.find_or_add({v, uint32_t(vt), uint32_t(vn)}, next);
    last = {m.serial, vt, vn, index};
    if (!added) return index;
    // Attributes are stored from the first vertex that has one (earlier vertices get the
    // default), so a mesh without uvs, normals or colours never allocates them.
    size_t at = m.mesh.positions.size();
    m.mesh.positions.push_back(positions_[corner.v]);  // equal to the canonical one's
    if (corner.vt != kNone) {
      pad(m.mesh.uvs, at, kNoUv);
      m.mesh.uvs.push_back(uvs_[corner.vt]);
    }
    if (corner.vn != kNone) {
      pad(m.mesh.normals, at, Normal3f());
      pad(m.has_normal, at, uint8_t(0));
      m.mesh.normals.push_back(normals_[corner.vn]);
      m.has_normal.push_back(1);
    }
    if (size_t(corner.v) < colors_.size()) {
      pad(m.mesh.colors, at, Rgb(1.f));
      m.mesh.colors.push_back(colors_[corner.v]);
    }
    return index;
  }

  // Assimp's texture coordinate for a corner without vt: (0, 0), flipped.
  static constexpr Point2f kNoUv{0, 1};

  template <typename T>
  static void pad(std::vector<T>& attribute, size_t size, const T& value) {
    if (attribute.size() < size) attribute.resize(size, value);
  }

  void material_library(const std::string& file) {
    if (file.empty()) fail("'mtllib' without a file name");
    std::error_code ec;
    std::filesystem::path path = std::filesystem::path(base_dir_) / file;
    if (!std::filesystem::exists(path, ec)) {
      warnings_.push_back(name_ + ":" + std::to_string(lines_.line_number) +
                          ": material library '" + file + "' not found (looked for " +
                          path.string() + "); its materials get the default grey");
      return;
    }
    std::vector<char> text = read_mesh_file(path.string());
    scene_.input_files.push_back(path.string());
    for (MtlMaterial& m :
         parse_mtl(std::string_view(text.data(), text.size()), path.string(), warnings_))
      library_.push_back(std::move(m));
    libraries_loaded_ = true;
  }

  TextureRef texture(const std::string& relative_path, const std::string& where) {
    if (relative_path.empty()) return {};
    std::string relative = relative_path;
    std::replace(relative.begin(), relative.end(), '\\', '/');
    std::filesystem::path full = std::filesystem::path(base_dir_) / relative;
    auto found = textures_.find(full.string());
    if (found != textures_.end()) return {found->second, 0};
    std::error_code ec;
    if (!std::filesystem::is_regular_file(full, ec))
      throw Error(name_ + ": " + where,
                  "texture '" + relative + "' does not exist (looked for " + full.string() + ")");
    auto index = int32_t(scene_.textures.size());
    scene_.textures.push_back(read_texture(full.string(), TextureEncoding::kSrgb));
    scene_.input_files.push_back(full.string());
    textures_[full.string()] = index;
    return {index, 0};
  }

  Material material(const MtlMaterial& m) {
    Material out;
    out.name = m.name;
    std::string where = "material '" + m.name + "'";
    PhongMaterial phong;
    phong.ambient = m.ambient;
    phong.diffuse = m.diffuse;
    phong.specular = m.specular;
    phong.shininess = m.shininess;
    phong.diffuse_texture = texture(m.diffuse_map, where + " (map_Kd)");
    out.model = phong;
    out.emission = m.emission;
    out.emission_texture = texture(m.emission_map, where + " (map_Ke)");
    return out;
  }

  // Drops what no corner had, fills normals a corner lacked from its faces, normalises.
  static void finish_attributes(MeshBuild& m) {
    size_t n = m.mesh.positions.size();
    if (!m.mesh.uvs.empty()) pad(m.mesh.uvs, n, kNoUv);
    if (!m.mesh.colors.empty()) pad(m.mesh.colors, n, Rgb(1.f));
    if (m.mesh.normals.empty()) return;
    pad(m.mesh.normals, n, Normal3f());
    pad(m.has_normal, n, uint8_t(0));
    auto unit = [](Vector3f v, bool& ok) {
      float length = std::sqrt(dot(v, v));
      ok = length > 0 && std::isfinite(length);
      return ok ? Normal3f(v / length) : Normal3f(0, 0, 1);
    };
    std::vector<Normal3f>& normals = m.mesh.normals;
    bool ok = false;
    for (size_t i = 0; i < normals.size(); ++i)
      if (m.has_normal[i]) {
        normals[i] = unit(to_vector(normals[i]), ok);
        m.has_normal[i] = ok;
      }
    std::vector<Vector3f> sums(normals.size());
    const std::vector<Point3f>& p = m.mesh.positions;
    const std::vector<uint32_t>& idx = m.mesh.indices;
    for (size_t t = 0; t + 2 < idx.size(); t += 3) {
      Vector3f n = cross(p[idx[t + 1]] - p[idx[t]], p[idx[t + 2]] - p[idx[t]]);  // area-weighted
      for (int k = 0; k < 3; ++k) sums[idx[t + k]] += n;
    }
    for (size_t i = 0; i < normals.size(); ++i)
      if (!m.has_normal[i]) normals[i] = unit(sums[i], ok);
  }

  Scene finish() {
    scene_.name = scene_name_of(name_);
    scene_.warnings = std::move(warnings_);
    // Assimp's material order: its default, the libraries' in file order, then names no
    // library defined, in order of use.
    std::vector<MtlMaterial> all;
    MtlMaterial fallback;
    fallback.name = "DefaultMaterial";
    all.push_back(fallback);
    std::map<std::string, size_t> by_name{{fallback.name, 0}};
    for (MtlMaterial& m : library_)
      if (by_name.emplace(m.name, all.size()).second) all.push_back(std::move(m));
    std::vector<int32_t> used;
    std::vector<MeshBuild*> meshes;
    for (std::vector<MeshBuild>& object : objects_)
      for (MeshBuild& m : object)
        if (!m.mesh.indices.empty()) meshes.push_back(&m);
    std::vector<size_t> material_of;
    for (MeshBuild* m : meshes) {
      std::string name = m->material.empty() ? "DefaultMaterial" : m->material;
      auto [it, added] = by_name.emplace(name, all.size());
      if (added) {
        MtlMaterial unknown;
        unknown.name = name;
        all.push_back(unknown);
        scene_.warnings.push_back(name_ + ": material '" + name + "' is not defined" +
                                  (libraries_loaded_ ? " in the material libraries" : "") +
                                  "; it gets the default grey");
      }
      material_of.push_back(it->second);
    }
    std::vector<int32_t> remap(all.size(), -1);
    for (size_t index : material_of) remap[index] = 0;
    for (size_t i = 0; i < all.size(); ++i)
      if (remap[i] == 0) {
        remap[i] = int32_t(scene_.materials.size());
        scene_.materials.push_back(material(all[i]));
      }
    if (scene_.materials.empty()) scene_.materials.push_back(material(fallback));
    for (size_t i = 0; i < meshes.size(); ++i) {
      MeshBuild& m = *meshes[i];
      finish_attributes(m);
      m.mesh.material = uint32_t(remap[material_of[i]]);
      // Grown by push_back: give back the spare capacity the scene would otherwise keep.
      m.mesh.indices.shrink_to_fit();
      m.mesh.positions.shrink_to_fit();
      m.mesh.normals.shrink_to_fit();
      m.mesh.uvs.shrink_to_fit();
      m.mesh.colors.shrink_to_fit();
      std::string object = m.object;
      uint32_t index = scene_.add_mesh(std::move(m.mesh));
      scene_.instances.back().name = object;
      scene_.instances.back().material = int32_t(scene_.meshes[index].material);
    }
    return std::move(scene_);
  }

  Lines& lines_;
  const std::string& name_;
  std::string base_dir_;
  std::vector<Point3f> positions_;
  std::vector<Rgb> colors_;  // only as long as the last vertex that had a colour
  std::vector<Point2f> uvs_;
  std::vector<Normal3f> normals_;
  std::vector<Corner> corners_;
  std::vector<uint32_t> polygon_;  // the current face's vertices
  // Per canonical v: the mesh vertex its last corner became, and with which vt and vn.
  struct LastUse {
    uint32_t mesh = ~0u;
    int32_t vt = 0, vn = 0;
    uint32_t vertex = 0;
  };
  std::vector<LastUse> last_use_;
  uint32_t mesh_count_ = 0;
  // Per v/vt/vn line, the first line with the same values, and the maps that find it.
  std::vector<int32_t> canonical_v_, canonical_vt_, canonical_vn_;
  FlatIndexMap<6> position_index_;
  FlatIndexMap<2> uv_index_;
  FlatIndexMap<3> normal_index_;
  // Objects in file order, each with its meshes in order of creation; faces go to the last.
  std::vector<std::vector<MeshBuild>> objects_;
  std::string material_;
  std::vector<MtlMaterial> library_;
  bool libraries_loaded_ = false;
  std::map<std::string, int32_t> textures_;
  std::vector<std::string> warnings_;
  Scene scene_;
};

}  // namespace

Scene load_obj_bytes(std::span<const char> bytes, const std::string& name,
                     const std::string& base_dir) {
  LineReader lines{std::string_view(bytes.data(), bytes.size())};
  return ObjReader<LineReader>(lines, name, base_dir).read();
}

Scene load_obj(const std::string& path) {
  FileLines lines(path);
  return ObjReader<FileLines>(lines, path, std::filesystem::path(path).parent_path().string())
      .read();
}

}  // namespace obscura
