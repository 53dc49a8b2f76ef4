#include "obscura/io/obj_loader.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>

#include <tbb/parallel_pipeline.h>
#include <tbb/task_arena.h>

#include "obscura/io/first_index_table.h"
#include "obscura/io/flat_index_map.h"
#include "obscura/io/gltf_missing_image.h"
#include "obscura/io/mesh_file.h"
#include "obscura/io/mtl_reader.h"
#include "obscura/io/obj_statements.h"
#include "obscura/io/text_blocks.h"
#include "obscura/io/texture_loader.h"
#include "obscura/math/error.h"

namespace obscura {

namespace {

constexpr int32_t kNone = -1;  // a corner without vt or vn

struct MeshBuild {
  Mesh mesh;
  std::string object;    // the instance's name
  std::string material;  // "" = DefaultMaterial
  // Each distinct (v, vt, vn) the faces use → its vertex, but for those held by
  // ObjReader::first_use_. The indices are canonical: the first of the v (vt, vn) lines with the
  // same values, so that a position written twice in the file is one vertex, as Assimp's vertex
  // joining made it.
  FlatIndexMap<3> corners;
  std::vector<uint8_t> has_normal;  // per vertex
  uint32_t serial = 0;              // which mesh this is, for ObjReader::first_use_
};

// Takes the statements of each block in file order and builds the scene: what depends on the
// lines before (index resolution, vertex sharing, objects, materials).
class ObjReader {
 public:
  ObjReader(const std::string& name, const std::string& base_dir)
      : name_(name), base_dir_(base_dir) {}

  void take(const ObjStatements& block) {
    const std::vector<ObjStatement>& statements = block.statements;
    constexpr size_t kAhead = 8;
    for (size_t i = 0; i < statements.size(); ++i) {
      if (i + kAhead < statements.size()) prefetch(block, statements[i + kAhead]);
      const ObjStatement& s = statements[i];
      line_number_ = first_line_ + s.line;
      switch (s.keyword) {
        case ObjKeyword::kV:
          vertex_position(&block.floats[s.begin], s.count);
          break;
        case ObjKeyword::kVt:
          texture_coordinate(&block.floats[s.begin]);
          break;
        case ObjKeyword::kVn:
          normal(&block.floats[s.begin]);
          break;
        case ObjKeyword::kF:
          face(block, s);
          break;
        case ObjKeyword::kObject:
        case ObjKeyword::kGroup: {
          const std::string& object = block.texts[s.begin];
          // An unnamed "o"/"g", or a "g" naming the current object, keeps the current object.
          if (!object.empty() &&
              !(s.keyword == ObjKeyword::kGroup && current() && current()->object == object))
            start_object(object);
          break;
        }
        case ObjKeyword::kUseMtl:
          use_material(block.texts[s.begin]);
          break;
        case ObjKeyword::kMtlLib:
          material_library(block.texts[s.begin]);
          break;
        case ObjKeyword::kError:
          fail(block.errors[size_t(s.error)]);
      }
    }
    first_line_ += block.lines;
  }

 private:
  struct Corner {
    int32_t v, vt, vn;
  };

  [[noreturn]] void fail(const std::string& message) const {
    throw Error(name_ + ":" + std::to_string(line_number_), message);
  }

  // The values a v, vt or vn line is shared by: a position's colour is part of it (white if it
  // has none), and texture coordinates are compared as written.
  static std::array<uint32_t, 6> position_key(const float* v, uint32_t count) {
    return count == 6 ? float_words(v[0], v[1], v[2], v[3], v[4], v[5])
                      : float_words(v[0], v[1], v[2], 1.f, 1.f, 1.f);
  }
  static std::array<uint32_t, 2> uv_key(const float* uv) { return float_words(uv[0], uv[1]); }
  static std::array<uint32_t, 3> normal_key(const float* n) {
    return float_words(n[0], n[1], n[2]);
  }

  // Brings in the table slots that the statement `ahead` will look up: each lookup of a large
  // file's tables is a cache miss, and taking several at once hides most of their latency.
  void prefetch(const ObjStatements& block, const ObjStatement& ahead) const {
    // `begin` indexes the floats only for these three (a face's indexes its corners).
    if (ahead.keyword == ObjKeyword::kV)
      position_index_.prefetch(hash_words(position_key(&block.floats[ahead.begin], ahead.count)));
    else if (ahead.keyword == ObjKeyword::kVt)
      uv_index_.prefetch(hash_words(uv_key(&block.floats[ahead.begin])));
    else if (ahead.keyword == ObjKeyword::kVn)
      normal_index_.prefetch(hash_words(normal_key(&block.floats[ahead.begin])));
  }

  void vertex_position(const float* v, uint32_t count) {
    positions_.push_back({v[0], v[1], v[2]});
    first_use_.emplace_back();
    if (count == 6) {
      if (colors_.size() < positions_.size() - 1) colors_.resize(positions_.size() - 1, Rgb(1.f));
      colors_.push_back({v[3], v[4], v[5]});
    }
    const auto key = position_key(v, count);
    canonical_v_.push_back(int32_t(position_index_.find_or_add(
        hash_words(key), uint32_t(positions_.size() - 1), [&](uint32_t j) {
          Point3f p = positions_[j];
          Rgb c = j < colors_.size() ? colors_[j] : Rgb(1.f);
          return float_words(p.x, p.y, p.z, c.r, c.g, c.b) == key;
        })));
  }

  void texture_coordinate(const float* uv) {
    uvs_.push_back({uv[0], uv[1]});
    const auto key = uv_key(uv);
    canonical_vt_.push_back(
        int32_t(uv_index_.find_or_add(hash_words(key), uint32_t(uvs_.size() - 1), [&](uint32_t j) {
          return float_words(uvs_[j].x, uvs_[j].y) == key;
        })));
  }

  void normal(const float* n) {
    normals_.push_back({n[0], n[1], n[2]});
    const auto key = normal_key(n);
    canonical_vn_.push_back(int32_t(
        normal_index_.find_or_add(hash_words(key), uint32_t(normals_.size() - 1), [&](uint32_t j) {
          return float_words(normals_[j].x, normals_[j].y, normals_[j].z) == key;
        })));
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
  int32_t resolve(int64_t i, size_t count, const char* what) {
    int64_t index = i > 0 ? i - 1 : int64_t(count) + i;
    if (i == 0 || index < 0 || index >= int64_t(count))
      fail(std::string("face refers to ") + what + " " + std::to_string(i) + ", but " +
           std::to_string(count) + " " + what + (count == 1 ? " is" : "s are") +
           " defined before this line");
    return int32_t(index);
  }

  Corner resolve(const ObjCorner& c) {
    return {resolve(c.v, positions_.size(), "vertex"),
            c.vt == kAbsentIndex ? kNone : resolve(c.vt, uvs_.size(), "texture coordinate"),
            c.vn == kAbsentIndex ? kNone : resolve(c.vn, normals_.size(), "normal")};
  }

  void face(const ObjStatements& block, const ObjStatement& s) {
    corners_.clear();
    for (uint32_t k = 0; k < s.count; ++k) corners_.push_back(resolve(block.corners[s.begin + k]));
    if (s.error >= 0) {
      // The indices read before the malformed one are checked first.
      const ObjCorner& c = block.corners[s.begin + s.count];
      const int64_t fields[3] = {c.v, c.vt, c.vn};
      const size_t counts[3] = {positions_.size(), uvs_.size(), normals_.size()};
      const char* what[3] = {"vertex", "texture coordinate", "normal"};
      for (int k = 0; k < s.partial; ++k)
        if (fields[k] != kAbsentIndex) resolve(fields[k], counts[k], what[k]);
      fail(block.errors[size_t(s.error)]);
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

  uint32_t vertex(MeshBuild& m, const Corner& corner) {
    auto v = uint32_t(canonical_v_[corner.v]);
    int32_t vt = corner.vt == kNone ? kNone : canonical_vt_[corner.vt];
    int32_t vn = corner.vn == kNone ? kNone : canonical_vn_[corner.vn];
    // A position's first (mesh, vt, vn) is looked up by its index, without the random access of
    // a hash table: in most files it is the only one. Later ones (seams, meshes sharing
    // positions) go to the mesh's table.
    FirstUse& first = first_use_[v];
    if (first.mesh == m.serial && first.vt == vt && first.vn == vn) return first.vertex;
    auto index = uint32_t(m.mesh.positions.size());
    if (first.mesh == FirstUse::kNone) {
      first = {m.serial, vt, vn, index};
    } else {
      auto [found, added] = m.corners.find_or_add({v, uint32_t(vt), uint32_t(vn)}, index);
      if (!added) return found;
    }
    // Attributes are stored from the first vertex that has one (earlier vertices get the
    // default), so a mesh without uvs, normals or colours never allocates them.
    size_t at = m.mesh.positions.size();
    m.mesh.positions.push_back(positions_[corner.v]);  // equal to the canonical one's
    if (corner.vt != kNone) {
      pad(m.mesh.uvs, at, kNoUv);
      const Point2f uv = uvs_[corner.vt];
      m.mesh.uvs.push_back({uv.x, 1 - uv.y});  // glTF's convention: v = 0 at the image's top
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
      warnings_.push_back(name_ + ":" + std::to_string(line_number_) + ": material library '" +
                          file + "' not found (looked for " + path.string() +
                          "); its materials get the default grey");
      return;
    }
    std::vector<char> text = read_mesh_file(path.string());
    scene_.input_files.push_back(path.string());
    for (MtlMaterial& m :
         parse_mtl(std::string_view(text.data(), text.size()), path.string(), warnings_))
      library_.push_back(std::move(m));
    libraries_loaded_ = true;
  }

  // An MTL texture: read where the MTL says, else under its base name next to the model (paths
  // from another machine, "C:\\Users\\…\\wood.png", are common in downloaded OBJs). One that
  // still cannot be used (missing, or a format we do not read, such as DDS) warns, as the glTF
  // loader does: a diffuse map shows the magenta/black checker, an emission map is left out.
  TextureRef texture(const std::string& relative_path, const std::string& where,
                     bool placeholder_if_unusable) {
    if (relative_path.empty()) return {};
    std::string relative = relative_path;
    std::replace(relative.begin(), relative.end(), '\\', '/');
    const std::filesystem::path full = std::filesystem::path(base_dir_) / relative;
    int32_t index = -1;
    if (auto found = textures_.find(full.string()); found != textures_.end()) {
      index = found->second;
    } else {
      index = read_mtl_texture(full, relative, relative_path, where);
      textures_[full.string()] = index;
    }
    if (index < 0 && placeholder_if_unusable) {
      if (placeholder_ < 0) {
        placeholder_ = int32_t(scene_.textures.size());
        scene_.textures.push_back(missing_image_placeholder());
      }
      index = placeholder_;
    }
    return index < 0 ? TextureRef{} : TextureRef{index, 0};
  }

  // The texture's index in the scene, or −1 (with a warning) when it cannot be used.
  int32_t read_mtl_texture(const std::filesystem::path& full, const std::string& relative,
                           const std::string& relative_path, const std::string& where) {
    std::error_code ec;
    std::string path = full.string(), why;
    if (!std::filesystem::is_regular_file(full, ec)) {
      if (std::optional<std::string> nearby = find_image_next_to_model(relative, base_dir_)) {
        warnings_.push_back(name_ + ": " + where + ": texture '" + relative_path +
                            "' was not found; using '" + image_uri_base_name(relative) +
                            "' found next to the model instead");
        path = *nearby;
      } else {
        why = "it does not exist (looked for " + full.string() + ")";
      }
    }
    if (why.empty()) {
      try {
        Texture decoded = read_texture(path, TextureEncoding::kSrgb, &warnings_);
        scene_.textures.push_back(std::move(decoded));
        scene_.input_files.push_back(path);
        return int32_t(scene_.textures.size() - 1);
      } catch (const Error& e) {
        why = e.what();
      }
    }
    warnings_.push_back(name_ + ": " + where + ": texture '" + relative_path +
                        "' cannot be used (" + why +
                        "); a diffuse map shows a magenta/black checker instead, an emission map "
                        "is left out");
    return -1;
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
    phong.diffuse_texture = texture(m.diffuse_map, where + " (map_Kd)", true);
    out.model = phong;
    out.emission = m.emission;
    out.emission_texture = texture(m.emission_map, where + " (map_Ke)", false);
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
    if (std::all_of(m.has_normal.begin(), m.has_normal.end(), [](uint8_t has) { return has; }))
      return;  // nothing to fill: skip the per-vertex sums
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

 public:
  Scene finish() {
    scene_.name = scene_name_of(name_);
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
    scene_.warnings = std::move(warnings_);  // the materials' texture warnings included
    return std::move(scene_);
  }

 private:
  const std::string& name_;
  size_t first_line_ = 1;   // of the block being taken
  size_t line_number_ = 0;  // of the statement being taken
  std::string base_dir_;
  std::vector<Point3f> positions_;
  std::vector<Rgb> colors_;   // only as long as the last vertex that had a colour
  std::vector<Point2f> uvs_;  // as written (v = 0 at the image's bottom)
  std::vector<Normal3f> normals_;
  std::vector<Corner> corners_;
  std::vector<uint32_t> polygon_;  // the current face's vertices
  // Per canonical v: the mesh, vt and vn of the first corner that used it, and its vertex.
  struct FirstUse {
    static constexpr uint32_t kNone = ~0u;
    uint32_t mesh = kNone;
    int32_t vt = 0, vn = 0;
    uint32_t vertex = 0;
  };
  std::vector<FirstUse> first_use_;
  uint32_t mesh_count_ = 0;
  // Per v/vt/vn line, the first line with the same values, and the maps that find it.
  std::vector<int32_t> canonical_v_, canonical_vt_, canonical_vn_;
  FirstIndexTable position_index_, uv_index_, normal_index_;
  // Objects in file order, each with its meshes in order of creation; faces go to the last.
  std::vector<std::vector<MeshBuild>> objects_;
  std::string material_;
  std::vector<MtlMaterial> library_;
  bool libraries_loaded_ = false;
  std::map<std::string, int32_t> textures_;  // by path; −1: cannot be used (warned once)
  int32_t placeholder_ = -1;                 // the checker, once some diffuse map needs it
  std::vector<std::string> warnings_;
  Scene scene_;
};

}  // namespace

namespace {

// Blocks are read in order, parsed on any thread, and taken by the reader in order: the scene is
// the same for any thread count. A few blocks in flight per thread bound the memory.
Scene read_obj(TextBlocks& blocks, const std::string& name, const std::string& base_dir) {
  struct Work {
    TextBlock block;
    ObjStatements statements;
  };
  using WorkPtr = std::shared_ptr<Work>;
  ObjReader reader(name, base_dir);
  const auto in_flight = size_t(2 * tbb::this_task_arena::max_concurrency());
  tbb::parallel_pipeline(
      in_flight,
      tbb::make_filter<void, WorkPtr>(tbb::filter_mode::serial_in_order,
                                      [&blocks](tbb::flow_control& control) {
                                        auto work = std::make_shared<Work>();
                                        if (blocks.next(work->block)) return work;
                                        control.stop();
                                        return WorkPtr();
                                      }) &
          tbb::make_filter<WorkPtr, WorkPtr>(tbb::filter_mode::parallel,
                                             [](WorkPtr work) {
                                               parse_obj_block(work->block.text, work->statements);
                                               work->block = {};  // the text is not needed now
                                               return work;
                                             }) &
          tbb::make_filter<WorkPtr, void>(
              tbb::filter_mode::serial_in_order,
              [&reader](const WorkPtr& work) { reader.take(work->statements); }));
  return reader.finish();
}

}  // namespace

Scene load_obj_bytes(std::span<const char> bytes, const std::string& name,
                     const std::string& base_dir) {
  TextBlocks blocks(bytes);
  return read_obj(blocks, name, base_dir);
}

Scene load_obj(const std::string& path) {
  TextBlocks blocks(path);
  return read_obj(blocks, path, std::filesystem::path(path).parent_path().string());
}

}  // namespace obscura
