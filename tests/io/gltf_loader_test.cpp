// The glTF loader against Khronos sample models (tests/data/gltf/). Expected counts come from two
// independent sources: the numbers in the shared asset collection's README, and the file's
// own JSON (accessor counts, node lists) read here with nlohmann::json rather than tinygltf.
// Transforms are checked against glm.
#include "obscura/io/gltf_loader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <map>
#include <nlohmann/json.hpp>
#include <set>

#include "obscura/math/error.h"
#include "run_command.h"
#include "test_paths.h"

namespace obscura {
namespace {

using nlohmann::json;

std::string sample(const std::string& relative) {
  // The example scenes already ship this one (scenes/assets/); the others are in tests/data/.
  if (relative.starts_with("MetalRoughSpheresNoTextures/"))
    return test::source_path("scenes/assets/gltf/MetalRoughSpheresNoTextures.glb");
  return test::data_path("gltf/" + relative);
}

std::vector<uint8_t> read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// A glTF file's JSON and, for .glb, its BIN chunk, read by hand from the GLB layout
// (12-byte header, then length-prefixed chunks).
struct GltfFile {
  json doc;
  std::vector<uint8_t> bin;

  explicit GltfFile(const std::string& path) {
    std::vector<uint8_t> bytes = read_bytes(path);
    if (path.ends_with(".glb")) {
      uint32_t json_length;
      std::memcpy(&json_length, &bytes[12], 4);
      doc = json::parse(bytes.begin() + 20, bytes.begin() + 20 + json_length);
      size_t bin_chunk = 20 + json_length;
      if (bin_chunk + 8 <= bytes.size()) {
        uint32_t bin_length;
        std::memcpy(&bin_length, &bytes[bin_chunk], 4);
        bin.assign(bytes.begin() + bin_chunk + 8, bytes.begin() + bin_chunk + 8 + bin_length);
      }
    } else {
      doc = json::parse(bytes.begin(), bytes.end());
    }
  }

  // Triangles as rendered (every node instance of every TRIANGLES primitive), and stored
  // (each distinct set of accessors once), walking the default scene's nodes.
  struct Counts {
    size_t rendered = 0, stored = 0, instances = 0;
  };
  Counts count() const {
    Counts c;
    std::set<std::string> geometry;
    std::function<void(int)> visit = [&](int n) {
      const json& node = doc["nodes"][n];
      if (node.contains("mesh")) {
        for (const json& p : doc["meshes"][node["mesh"].get<int>()]["primitives"]) {
          size_t count =
              p.contains("indices")
                  ? doc["accessors"][p["indices"].get<int>()]["count"].get<size_t>()
                  : doc["accessors"][p["attributes"]["POSITION"].get<int>()]["count"].get<size_t>();
          c.rendered += count / 3;
          ++c.instances;
          if (geometry.insert(p["attributes"].dump() + p.value("indices", json(-1)).dump()).second)
            c.stored += count / 3;
        }
      }
      for (const json& child : node.value("children", json::array())) visit(child.get<int>());
    };
    for (const json& root : doc["scenes"][doc.value("scene", 0)]["nodes"]) visit(root.get<int>());
    return c;
  }

  // Distinct (texture, colour-or-data) uses by materials: base colour and emission are colour.
  size_t texture_uses() const {
    std::set<std::pair<int, bool>> uses;
    for (const json& m : doc.value("materials", json::array())) {
      auto use = [&](const json& slot, bool colour) {
        if (slot.is_object() && slot.contains("index"))
          uses.insert({slot["index"].get<int>(), colour});
      };
      const json pbr = m.value("pbrMetallicRoughness", json::object());
      use(pbr.value("baseColorTexture", json()), true);
      use(pbr.value("metallicRoughnessTexture", json()), false);
      use(m.value("normalTexture", json()), false);
      use(m.value("occlusionTexture", json()), false);
      use(m.value("emissiveTexture", json()), true);
    }
    return uses.size();
  }

  glm::dmat4 local(int n) const {
    const json& node = doc["nodes"][n];
    if (node.contains("matrix")) {
      std::vector<double> m = node["matrix"].get<std::vector<double>>();
      return glm::make_mat4(m.data());  // both column-major
    }
    glm::dvec3 t(0), s(1);
    glm::dquat q(1, 0, 0, 0);
    if (node.contains("translation"))
      t = {node["translation"][0], node["translation"][1], node["translation"][2]};
    if (node.contains("scale")) s = {node["scale"][0], node["scale"][1], node["scale"][2]};
    if (node.contains("rotation"))
      q = glm::dquat(node["rotation"][3], node["rotation"][0], node["rotation"][1],
                     node["rotation"][2]);
    return glm::translate(glm::dmat4(1), t) * glm::mat4_cast(q) * glm::scale(glm::dmat4(1), s);
  }

  // POSITION of a GLB accessor (float VEC3).
  std::vector<glm::dvec3> positions(int accessor) const {
    const json& a = doc["accessors"][accessor];
    const json& view = doc["bufferViews"][a["bufferView"].get<int>()];
    size_t stride = view.value("byteStride", 12);
    size_t begin = view.value("byteOffset", 0) + a.value("byteOffset", 0);
    std::vector<glm::dvec3> out;
    for (size_t i = 0; i < a["count"].get<size_t>(); ++i) {
      float xyz[3];
      std::memcpy(xyz, &bin[begin + i * stride], 12);
      out.emplace_back(xyz[0], xyz[1], xyz[2]);
    }
    return out;
  }
};

struct SampleCase {
  std::string file;
  size_t readme_triangles;  // the asset collection's README, "triangles" column
};

void PrintTo(const SampleCase& c, std::ostream* os) {
  *os << c.file;
}

class GltfSample : public testing::TestWithParam<SampleCase> {};

TEST_P(GltfSample, CountsMatchTheFileAndTheAssetReadme) {
  const SampleCase& c = GetParam();
  Scene scene = load_gltf(sample(c.file));
  GltfFile file(sample(c.file));
  GltfFile::Counts expected = file.count();
  SceneStats s = scene.stats();
  EXPECT_EQ(s.triangles, c.readme_triangles);
  EXPECT_EQ(s.triangles, expected.rendered);
  EXPECT_EQ(s.unique_triangles, expected.stored);
  EXPECT_EQ(s.instances, expected.instances);
  EXPECT_EQ(s.textures, file.texture_uses());
  // One material per glTF material, plus glTF's default one when a primitive has none.
  bool uses_default = false;
  for (const json& m : file.doc["meshes"])
    for (const json& p : m["primitives"]) uses_default |= !p.contains("material");
  EXPECT_EQ(s.materials,
            file.doc.value("materials", json::array()).size() + (uses_default ? 1 : 0));
  EXPECT_NO_THROW(scene.validate());
}

INSTANTIATE_TEST_SUITE_P(
    Khronos, GltfSample,
    testing::Values(SampleCase{"Box/Box.glb", 12}, SampleCase{"Box/glTF/Box.gltf", 12},
                    SampleCase{"BoxTextured/BoxTextured.glb", 12},
                    SampleCase{"BoxTextured/glTF/BoxTextured.gltf", 12},
                    SampleCase{"BoxVertexColors/BoxVertexColors.glb", 12},
                    SampleCase{"Duck/Duck.glb", 4212}, SampleCase{"Avocado/glTF/Avocado.gltf", 682},
                    SampleCase{"WaterBottle/glTF/WaterBottle.gltf", 4510},
                    SampleCase{"Cameras/Cameras.gltf", 2},
                    SampleCase{"MetalRoughSpheresNoTextures/MetalRoughSpheresNoTextures.glb",
                               1040409},
                    SampleCase{"OrientationTest/OrientationTest.glb", 524},
                    SampleCase{"TextureCoordinateTest/TextureCoordinateTest.glb", 10},
                    SampleCase{"AnimatedCube/glTF/AnimatedCube.gltf", 12},
                    SampleCase{"BoxAnimated/BoxAnimated.glb", 254},
                    SampleCase{"Suzanne/glTF/Suzanne.gltf", 3936}),
    [](const testing::TestParamInfo<SampleCase>& info) {
      std::string name = info.param.file.substr(info.param.file.rfind('/') + 1);
      for (char& ch : name)
        if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
      return name;
    });

TEST(GltfLoader, MetalRoughSpheresKeepsInstancing) {
  // README: 98 spheres share one accessor: 12,209 unique triangles, 1,040,409 rendered.
  Scene scene = load_gltf(sample("MetalRoughSpheresNoTextures/MetalRoughSpheresNoTextures.glb"));
  std::map<uint32_t, int> uses;
  for (const Instance& i : scene.instances) ++uses[i.mesh];
  int most = 0;
  for (auto [mesh, n] : uses) most = std::max(most, n);
  EXPECT_EQ(most, 98);
  EXPECT_EQ(scene.stats().unique_triangles, 12209u);
  EXPECT_EQ(scene.stats().triangles, 1040409u);
}

TEST(GltfLoader, OrientationTestNodesLandWhereGlmPutsThem) {
  std::string path = sample("OrientationTest/OrientationTest.glb");
  Scene scene = load_gltf(path);
  GltfFile file(path);
  std::map<std::string, int> node_by_name;
  for (size_t n = 0; n < file.doc["nodes"].size(); ++n)
    node_by_name[file.doc["nodes"][n].value("name", "")] = int(n);
  int checked = 0;
  for (const Instance& instance : scene.instances) {
    ASSERT_TRUE(node_by_name.count(instance.name)) << instance.name;
    int n = node_by_name[instance.name];
    glm::dmat4 world = file.local(n);  // every node here is a root
    int mesh = file.doc["nodes"][n]["mesh"].get<int>();
    int accessor = file.doc["meshes"][mesh]["primitives"][0]["attributes"]["POSITION"].get<int>();
    glm::dvec3 lo(1e30), hi(-1e30);
    for (glm::dvec3 p : file.positions(accessor)) {
      glm::dvec3 w = glm::dvec3(world * glm::dvec4(p, 1));
      lo = glm::min(lo, w), hi = glm::max(hi, w);
    }
    Bounds3f ours;
    for (Point3f p : scene.meshes[instance.mesh].positions)
      ours = unite(ours, instance.world_from_object(p));
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(ours.min[k], lo[k], 1e-4) << instance.name << " axis " << k;
      EXPECT_NEAR(ours.max[k], hi[k], 1e-4) << instance.name << " axis " << k;
    }
    ++checked;
  }
  EXPECT_EQ(checked, 13);
  // The arrows named X sit on the X axis at ±5, and so on (the sample's layout).
  for (const Instance& instance : scene.instances) {
    Bounds3f b;
    for (Point3f p : scene.meshes[instance.mesh].positions)
      b = unite(b, instance.world_from_object(p));
    if (instance.name == "ArrowX1") {
      EXPECT_GT(b.center().x, 3);
    }
    if (instance.name == "ArrowY2") {
      EXPECT_LT(b.center().y, -3);
    }
    if (instance.name == "ArrowZ1") {
      EXPECT_GT(b.center().z, 3);
    }
  }
}

TEST(GltfLoader, AChildIsAnimatedByItsAncestorsAndItself) {
  // BoxAnimated: node 2 (the rotating box) is a child of 1, itself a child of 0, whose
  // translation is animated: the box's keys cover both channels.
  std::string path = sample("BoxAnimated/BoxAnimated.glb");
  GltfFile file(path);
  Scene scene = load_gltf(path);
  ASSERT_EQ(scene.instances.size(), 2u);
  bool found = false;
  for (const Instance& instance : scene.instances) {
    if (!instance.animated()) continue;
    found = true;
    // It is animated by node 0's translation (0–3.71 s) and its own rotation (0–2.5 s).
    EXPECT_NEAR(instance.motion.front().time_seconds, 0, 1e-6);
    EXPECT_NEAR(instance.motion.back().time_seconds, 3.708, 0.01);
  }
  EXPECT_TRUE(found);
}

TEST(GltfLoader, AnimatedCubeRotationKeysMatchTheQuaternions) {
  std::string path = sample("AnimatedCube/glTF/AnimatedCube.gltf");
  Scene scene = load_gltf(path);
  ASSERT_EQ(scene.instances.size(), 1u);
  const Instance& cube = scene.instances[0];
  ASSERT_TRUE(cube.animated());
  EXPECT_NEAR(cube.motion.front().time_seconds, 0, 1e-6);
  EXPECT_NEAR(cube.motion.back().time_seconds, 2, 1e-3);
  // Each key is a pure rotation: it preserves lengths and has determinant +1.
  for (const TransformKey& key : cube.motion) {
    Vector3d x = key.world_from_object(Vector3d(1, 0, 0));
    EXPECT_NEAR(length(x), 1, 1e-6);
    EXPECT_FALSE(key.world_from_object.swaps_handedness());
  }
}

TEST(GltfLoader, CamerasSampleGivesBothCamerasWithTheFileValues) {
  Scene scene = load_gltf(sample("Cameras/Cameras.gltf"));
  ASSERT_EQ(scene.cameras.size(), 2u);
  const Camera& perspective = scene.cameras[0];
  const Camera& orthographic = scene.cameras[1];
  // README / file: perspective yfov 0.7 rad, aspect 1.0, znear 0.01, zfar 100.
  ASSERT_TRUE(std::holds_alternative<Perspective>(perspective.projection));
  EXPECT_NEAR(perspective.fov_degrees().y, 0.7 * 180 / 3.14159265358979, 1e-9);
  EXPECT_DOUBLE_EQ(perspective.film.image_aspect(), 1.0);
  EXPECT_DOUBLE_EQ(perspective.near_m, 0.01);
  EXPECT_DOUBLE_EQ(perspective.far_m, 100);
  // Orthographic xmag = ymag = 1.0 (a 2 × 2 m view), znear 0.01, zfar 100.
  ASSERT_TRUE(std::holds_alternative<Orthographic>(orthographic.projection));
  const auto& o = std::get<Orthographic>(orthographic.projection);
  EXPECT_DOUBLE_EQ(o.view_height_m, 2.0);
  EXPECT_DOUBLE_EQ(*o.view_width_m, 2.0);
  EXPECT_DOUBLE_EQ(orthographic.near_m, 0.01);
  EXPECT_DOUBLE_EQ(orthographic.far_m, 100);
  // Both nodes are translated to (0.5, 0.5, 3) and look down −Z.
  for (const Camera& c : scene.cameras) {
    Point3d eye = c.world_from_camera.at(0)(Point3d(0, 0, 0));
    EXPECT_NEAR(eye.x, 0.5, 1e-12);
    EXPECT_NEAR(eye.y, 0.5, 1e-12);
    EXPECT_NEAR(eye.z, 3.0, 1e-12);
    Vector3d forward = c.world_from_camera.at(0)(Vector3d(0, 0, -1));
    EXPECT_NEAR(forward.z, -1, 1e-12);
  }
}

TEST(GltfLoader, MaterialsTexturesAndVertexAttributes) {
  // WaterBottle: base colour, metal-rough (also the occlusion map), normal and emissive textures.
  // tests/data keeps its PNGs at 64² (see tests/data/README.md).
  Scene bottle = load_gltf(sample("WaterBottle/glTF/WaterBottle.gltf"));
  ASSERT_EQ(bottle.materials.size(), 1u);
  const auto& mr = std::get<MetallicRoughnessMaterial>(bottle.materials[0].model);
  EXPECT_TRUE(mr.base_color_texture.valid());
  EXPECT_TRUE(mr.metallic_roughness_texture.valid());
  EXPECT_TRUE(mr.occlusion_texture.valid());
  EXPECT_TRUE(bottle.materials[0].normal_texture.valid());
  EXPECT_TRUE(bottle.materials[0].emission_texture.valid());
  EXPECT_EQ(bottle.textures[mr.base_color_texture.texture].encoding, TextureEncoding::kSrgb);
  EXPECT_EQ(bottle.textures[mr.metallic_roughness_texture.texture].encoding,
            TextureEncoding::kLinear);
  EXPECT_EQ(bottle.textures[mr.base_color_texture.texture].width, 64);
  const Mesh& m = bottle.meshes[0];
  EXPECT_EQ(m.normals.size(), m.positions.size());
  EXPECT_EQ(m.uvs.size(), m.positions.size());

  Scene textured = load_gltf(sample("BoxTextured/glTF/BoxTextured.gltf"));  // external PNG
  ASSERT_EQ(textured.textures.size(), 1u);
  EXPECT_EQ(textured.textures[0].width, 256);
  EXPECT_EQ(textured.textures[0].height, 256);
  EXPECT_FALSE(textured.textures[0].texels_8bit.empty());

  Scene colors = load_gltf(sample("BoxVertexColors/BoxVertexColors.glb"));
  EXPECT_EQ(colors.meshes[0].colors.size(), colors.meshes[0].positions.size());
}

TEST(GltfLoader, CyclesCornellUsesSpecularZeroAndEmissiveStrength) {
  // data/reference/cornell/README.md: every material has KHR_materials_specular colour 0 (purely
  // diffuse), and the light has KHR_materials_emissive_strength 15 on emissive factor 1.
  Scene scene = load_gltf(test::source_path("data/reference/cornell/cornell.glb"));
  bool light = false;
  for (const Material& m : scene.materials) {
    const auto& mr = std::get<MetallicRoughnessMaterial>(m.model);
    EXPECT_TRUE(mr.purely_diffuse()) << m.name;
    if (m.name == "light") {
      light = true;
      EXPECT_EQ(m.emission, Rgb(15.f));
    }
    if (m.name == "red") {
      EXPECT_NEAR(mr.base_color.r, 0.63f, 1e-6);
    }
  }
  EXPECT_TRUE(light);
  ASSERT_EQ(scene.cameras.size(), 1u);
  EXPECT_NEAR(scene.cameras[0].fov_degrees().y, 0.6911112070083618 * 180 / 3.14159265358979, 1e-6);
}

// --- Bad input: a clear obscura::Error naming the file and the place, never a crash. ---

class GltfBadInput : public testing::Test {
 protected:
  std::string dir = test::make_temp_dir("obscura-gltf");

  std::string write(const std::string& name, const std::string& text) {
    std::string path = dir + "/" + name;
    std::ofstream(path, std::ios::binary) << text;
    return path;
  }
  // A one-triangle glTF whose buffer holds `positions` (3 floats each) and `indices` (uint16),
  // embedded as base64.
  std::string triangle(const std::string& name, std::vector<float> positions,
                       std::vector<uint16_t> indices, int position_accessor = 0, int mode = 4) {
    std::vector<uint8_t> bytes(positions.size() * 4 + indices.size() * 2);
    std::memcpy(bytes.data(), positions.data(), positions.size() * 4);
    std::memcpy(bytes.data() + positions.size() * 4, indices.data(), indices.size() * 2);
    static const char* b64 = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string encoded;
    for (size_t i = 0; i < bytes.size(); i += 3) {
      uint32_t v = bytes[i] << 16 | (i + 1 < bytes.size() ? bytes[i + 1] << 8 : 0) |
                   (i + 2 < bytes.size() ? bytes[i + 2] : 0);
      encoded += b64[v >> 18 & 63];
      encoded += b64[v >> 12 & 63];
      encoded += i + 1 < bytes.size() ? b64[v >> 6 & 63] : '=';
      encoded += i + 2 < bytes.size() ? b64[v & 63] : '=';
    }
    json doc = {
        {"asset", {{"version", "2.0"}}},
        {"scenes", {{{"nodes", {0}}}}},
        {"nodes", {{{"mesh", 0}}}},
        {"meshes",
         {{{"primitives",
            {{{"attributes", {{"POSITION", position_accessor}}},
              {"indices", 1},
              {"mode", mode}}}}}}},
        {"buffers",
         {{{"byteLength", bytes.size()},
           {"uri", "data:application/octet-stream;base64," + encoded}}}},
        {"bufferViews",
         {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", positions.size() * 4}},
          {{"buffer", 0},
           {"byteOffset", positions.size() * 4},
           {"byteLength", indices.size() * 2}}}},
        {"accessors",
         {{{"bufferView", 0},
           {"componentType", 5126},
           {"count", positions.size() / 3},
           {"type", "VEC3"}},
          {{"bufferView", 1},
           {"componentType", 5123},
           {"count", indices.size()},
           {"type", "SCALAR"}}}},
    };
    return write(name, doc.dump());
  }
  void expect_error(const std::string& path, const std::vector<std::string>& fragments) {
    try {
      load_gltf(path);
      ADD_FAILURE() << "no error for " << path;
    } catch (const Error& e) {
      for (const std::string& f : fragments) EXPECT_THAT(e.what(), testing::HasSubstr(f));
    }
  }
};

TEST_F(GltfBadInput, AWellFormedTriangleLoads) {
  Scene scene = load_gltf(triangle("ok.gltf", {0, 0, 0, 1, 0, 0, 0, 1, 0}, {0, 1, 2}));
  EXPECT_EQ(scene.stats().triangles, 1u);
}

TEST_F(GltfBadInput, StripsAndFansBecomeTrianglesFacingTheSameWay) {
  // A unit square in the z = 0 plane, as a strip (0 1 2 3) and as a fan (0 1 3 2): two
  // triangles each, both facing +Z like the strip's first triangle.
  std::vector<float> square = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};
  for (auto [mode, order] : {std::pair{5, std::vector<uint16_t>{0, 1, 2, 3}},
                             std::pair{6, std::vector<uint16_t>{0, 1, 3, 2}}}) {
    Scene scene =
        load_gltf(triangle("mode" + std::to_string(mode) + ".gltf", square, order, 0, mode));
    const Mesh& m = scene.meshes[0];
    ASSERT_EQ(m.triangle_count(), 2u) << "mode " << mode;
    for (size_t t = 0; t < 6; t += 3) {
      Vector3f n = cross(m.positions[m.indices[t + 1]] - m.positions[m.indices[t]],
                         m.positions[m.indices[t + 2]] - m.positions[m.indices[t]]);
      EXPECT_GT(n.z, 0) << "mode " << mode << " triangle " << t / 3;
    }
  }
}

TEST_F(GltfBadInput, MissingFile) {
  expect_error(dir + "/nowhere.glb", {"nowhere.glb", "does not exist"});
}

TEST_F(GltfBadInput, TruncatedGlb) {
  std::vector<uint8_t> box = read_bytes(sample("Box/Box.glb"));
  for (size_t keep : {size_t(0), size_t(8), size_t(20), box.size() / 2, box.size() - 10}) {
    std::string path = write("truncated" + std::to_string(keep) + ".glb",
                             std::string(box.begin(), box.begin() + keep));
    expect_error(path, {"truncated" + std::to_string(keep) + ".glb"});
  }
}

TEST_F(GltfBadInput, MalformedJson) {
  expect_error(write("bad.gltf", "{\"asset\": {"), {"bad.gltf"});
}

TEST_F(GltfBadInput, AccessorIndexOutOfRange) {
  expect_error(triangle("accessor.gltf", {0, 0, 0, 1, 0, 0, 0, 1, 0}, {0, 1, 2}, 7),
               {"accessor.gltf", "meshes[0].primitives[0]", "accessor index 7"});
}

TEST_F(GltfBadInput, FaceIndexPastTheVertexCount) {
  expect_error(triangle("index.gltf", {0, 0, 0, 1, 0, 0, 0, 1, 0}, {0, 1, 5}),
               {"index.gltf", "meshes[0].primitives[0].indices", "past the vertex count 3"});
}

TEST_F(GltfBadInput, NanPositions) {
  expect_error(triangle("nan.gltf", {0, 0, 0, std::nanf(""), 0, 0, 0, 1, 0}, {0, 1, 2}),
               {"nan.gltf", "POSITION", "vertex 1", "not finite"});
}

TEST_F(GltfBadInput, MissingTextureIsOneWarningAndAVisiblePlaceholder) {
  // BoxTextured.gltf copied without its PNG (and with its .bin): it still loads, its base colour
  // shows the missing-image checker (gltf_missing_image_test.cpp), and one warning names the file.
  std::filesystem::copy(sample("BoxTextured/glTF/BoxTextured.gltf"), dir + "/BoxTextured.gltf");
  std::filesystem::copy(sample("BoxTextured/glTF/BoxTextured0.bin"), dir + "/BoxTextured0.bin");
  Scene scene = load_gltf(dir + "/BoxTextured.gltf");
  int warnings = 0;
  for (const std::string& w : scene.warnings)
    if (w.find("CesiumLogoFlat.png") != std::string::npos) {
      ++warnings;
      EXPECT_THAT(w, testing::HasSubstr("BoxTextured.gltf: images[0]"));
    }
  EXPECT_EQ(warnings, 1);
  ASSERT_FALSE(scene.materials.empty());
  const auto& mr = std::get<MetallicRoughnessMaterial>(scene.materials[0].model);
  ASSERT_TRUE(mr.base_color_texture.valid());
  EXPECT_EQ(scene.textures.at(size_t(mr.base_color_texture.texture)).name,
            "missing-image placeholder");
}

TEST_F(GltfBadInput, CliReportsTheErrorAndExitsOne) {
  std::string path = triangle("cli.gltf", {0, 0, 0, 1, 0, 0, 0, 1, 0}, {0, 1, 9});
  test::CommandResult r = test::run_cli("info " + path);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.output, testing::HasSubstr("past the vertex count"));
}

}  // namespace
}  // namespace obscura
