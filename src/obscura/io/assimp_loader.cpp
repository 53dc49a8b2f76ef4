#include "obscura/io/assimp_loader.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/Importer.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>

#include "obscura/io/texture_loader.h"
#include "obscura/math/error.h"

namespace obscura {

namespace {

Rgb color(const aiMaterial& m, const char* key, unsigned type, unsigned index, Rgb fallback) {
  aiColor3D c;
  if (m.Get(key, type, index, c) != AI_SUCCESS) return fallback;
  return {c.r, c.g, c.b};
}

class AssimpImporter {
 public:
  AssimpImporter(const aiScene& ai, std::string file) : ai_(ai), file_(std::move(file)) {}

  Scene import() {
    scene_.name = std::filesystem::path(file_).stem().string();
    for (unsigned i = 0; i < ai_.mNumMaterials; ++i) scene_.materials.push_back(material(i));
    if (scene_.materials.empty()) {
      Material grey;
      grey.name = "default";
      scene_.materials.push_back(grey);
    }
    for (unsigned i = 0; i < ai_.mNumMeshes; ++i) scene_.meshes.push_back(mesh(i));
    if (ai_.mRootNode) visit(*ai_.mRootNode, Matrix4::identity(), 0);
    drop_unused_materials();
    return std::move(scene_);
  }

 private:
  TextureRef texture(const aiMaterial& m, aiTextureType type, const std::string& where) {
    aiString path;
    if (m.GetTexture(type, 0, &path) != AI_SUCCESS || path.length == 0) return {};
    std::string relative = path.C_Str();
    std::replace(relative.begin(), relative.end(), '\\', '/');
    if (!relative.empty() && relative[0] == '*')
      throw Error(file_ + ": " + where, "embedded textures are not supported in this format");
    std::filesystem::path full = std::filesystem::path(file_).parent_path() / relative;
    auto found = textures_.find(full.string());
    if (found != textures_.end()) return {found->second, 0};
    std::error_code ec;
    if (!std::filesystem::is_regular_file(full, ec))
      throw Error(file_ + ": " + where,
                  "texture '" + relative + "' does not exist (looked for " + full.string() + ")");
    Texture t = read_texture(full.string(), TextureEncoding::kSrgb, &scene_.warnings);
    scene_.input_files.push_back(full.string());
    auto index = int32_t(scene_.textures.size());
    scene_.textures.push_back(std::move(t));
    textures_[full.string()] = index;
    return {index, 0};
  }

  Material material(unsigned index) {
    const aiMaterial& am = *ai_.mMaterials[index];
    aiString name;
    am.Get(AI_MATKEY_NAME, name);
    Material m;
    m.name = name.length ? name.C_Str() : "material " + std::to_string(index);
    std::string where = "material '" + m.name + "'";
    PhongMaterial phong;
    phong.ambient = color(am, AI_MATKEY_COLOR_AMBIENT, Rgb());
    phong.diffuse = color(am, AI_MATKEY_COLOR_DIFFUSE, Rgb(0.8f));
    phong.specular = color(am, AI_MATKEY_COLOR_SPECULAR, Rgb());
    float shininess = 0;
    if (am.Get(AI_MATKEY_SHININESS, shininess) == AI_SUCCESS)
      phong.shininess = std::max(0.f, shininess);
    phong.diffuse_texture = texture(am, aiTextureType_DIFFUSE, where + " (map_Kd)");
    m.model = phong;
    m.emission = color(am, AI_MATKEY_COLOR_EMISSIVE, Rgb());
    m.emission_texture = texture(am, aiTextureType_EMISSIVE, where + " (map_Ke)");
    return m;
  }

  Mesh mesh(unsigned index) {
    const aiMesh& am = *ai_.mMeshes[index];
    Mesh mesh;
    mesh.name = am.mName.length ? am.mName.C_Str() : "mesh " + std::to_string(index);
    std::string where = file_ + ": mesh '" + mesh.name + "'";
    mesh.material = am.mMaterialIndex < scene_.materials.size() ? am.mMaterialIndex : 0;
    mesh.positions.resize(am.mNumVertices);
    for (unsigned i = 0; i < am.mNumVertices; ++i) {
      const aiVector3D& p = am.mVertices[i];
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
        throw Error(where, "vertex " + std::to_string(i) + " is not finite (NaN or infinity)");
      mesh.positions[i] = {p.x, p.y, p.z};
    }
    if (am.HasNormals()) {
      mesh.normals.resize(am.mNumVertices);
      for (unsigned i = 0; i < am.mNumVertices; ++i)
        mesh.normals[i] = {am.mNormals[i].x, am.mNormals[i].y, am.mNormals[i].z};
    }
    if (am.HasTextureCoords(0)) {
      mesh.uvs.resize(am.mNumVertices);
      for (unsigned i = 0; i < am.mNumVertices; ++i)
        mesh.uvs[i] = {am.mTextureCoords[0][i].x, am.mTextureCoords[0][i].y};
    }
    if (am.HasTangentsAndBitangents() && am.HasNormals()) {
      mesh.tangents.resize(am.mNumVertices);
      for (unsigned i = 0; i < am.mNumVertices; ++i) {
        Vector3f t(am.mTangents[i].x, am.mTangents[i].y, am.mTangents[i].z);
        Vector3f b(am.mBitangents[i].x, am.mBitangents[i].y, am.mBitangents[i].z);
        Vector3f n(am.mNormals[i].x, am.mNormals[i].y, am.mNormals[i].z);
        mesh.tangents[i] = {t.x, t.y, t.z, dot(cross(n, t), b) < 0 ? -1.f : 1.f};
      }
    }
    if (am.HasVertexColors(0)) {
      mesh.colors.resize(am.mNumVertices);
      for (unsigned i = 0; i < am.mNumVertices; ++i)
        mesh.colors[i] = {am.mColors[0][i].r, am.mColors[0][i].g, am.mColors[0][i].b};
    }
    mesh.indices.reserve(size_t(am.mNumFaces) * 3);
    for (unsigned f = 0; f < am.mNumFaces; ++f) {
      const aiFace& face = am.mFaces[f];
      if (face.mNumIndices != 3) continue;  // points and lines left by triangulation
      for (unsigned k = 0; k < 3; ++k) {
        if (face.mIndices[k] >= am.mNumVertices)
          throw Error(where, "face " + std::to_string(f) + " refers to vertex " +
                                 std::to_string(face.mIndices[k]) + ", past the vertex count " +
                                 std::to_string(am.mNumVertices));
        mesh.indices.push_back(face.mIndices[k]);
      }
    }
    return mesh;
  }

  void visit(const aiNode& node, const Matrix4& world_from_parent, int depth) {
    if (depth > 256) throw Error(file_, "node hierarchy deeper than 256 levels");
    const aiMatrix4x4& a = node.mTransformation;  // row-major, column vectors, as ours
    Matrix4 local = Matrix4::from_rows({{{a.a1, a.a2, a.a3, a.a4},
                                         {a.b1, a.b2, a.b3, a.b4},
                                         {a.c1, a.c2, a.c3, a.c4},
                                         {a.d1, a.d2, a.d3, a.d4}}});
    Matrix4 world = world_from_parent * local;
    std::optional<Matrix4> inv = inverse(world);
    for (unsigned i = 0; i < node.mNumMeshes && inv; ++i) {
      if (node.mMeshes[i] >= scene_.meshes.size())
        throw Error(file_, "node mesh index out of range");
      if (scene_.meshes[node.mMeshes[i]].indices.empty()) continue;
      Instance instance;
      instance.name = node.mName.length ? node.mName.C_Str() : scene_.meshes[node.mMeshes[i]].name;
      instance.mesh = node.mMeshes[i];
      instance.material = int32_t(scene_.meshes[node.mMeshes[i]].material);
      instance.world_from_object = Transform(world, *inv);
      scene_.instances.push_back(std::move(instance));
    }
    for (unsigned c = 0; c < node.mNumChildren; ++c) visit(*node.mChildren[c], world, depth + 1);
  }

  // Assimp's OBJ reader always adds a "DefaultMaterial"; keep only materials something uses.
  void drop_unused_materials() {
    std::vector<int32_t> remap(scene_.materials.size(), -1);
    for (const Mesh& m : scene_.meshes) remap[m.material] = 0;
    std::vector<Material> kept;
    for (size_t i = 0; i < remap.size(); ++i)
      if (remap[i] == 0) {
        remap[i] = int32_t(kept.size());
        kept.push_back(std::move(scene_.materials[i]));
      }
    if (kept.empty()) return;
    scene_.materials = std::move(kept);
    for (Mesh& m : scene_.meshes) m.material = uint32_t(remap[m.material]);
    for (Instance& i : scene_.instances) i.material = remap[i.material];
  }

  const aiScene& ai_;
  std::string file_;
  Scene scene_;
  std::map<std::string, int32_t> textures_;
};

}  // namespace

Scene load_with_assimp(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw Error(path, "file does not exist");
  Assimp::Importer importer;
  // Drop points and lines rather than render them as degenerate triangles.
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE,
                              aiPrimitiveType_POINT | aiPrimitiveType_LINE);
  const aiScene* ai = importer.ReadFile(
      path, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | aiProcess_SortByPType |
                aiProcess_FlipUVs | aiProcess_ValidateDataStructure);
  if (!ai) throw Error(path, std::string("cannot import: ") + importer.GetErrorString());
  if (ai->mFlags & AI_SCENE_FLAGS_INCOMPLETE) throw Error(path, "the file is incomplete");
  return AssimpImporter(*ai, path).import();
}

}  // namespace obscura
