// Skins and morph targets posed at a time, against positions computed here with glm from the
// files' own accessors (read by tests/io/gltf_reference_reader.h, not by the loader under test):
// SimpleSkin (two joints, a rotation animation) and AnimatedMorphCube (two targets, a 'weights'
// animation), plus small in-memory files for the default-weight rules and bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "gltf_hostile.h"
#include "gltf_reference_reader.h"
#include "obscura/io/gltf_loader.h"
#include "test_paths.h"

namespace obscura::test {
namespace {

GltfLoadOptions at_time(double t) {
  GltfLoadOptions o;
  o.time_s = t;
  return o;
}

// The value of a LINEAR channel at `t` (width numbers per key), clamped outside its keys.
std::vector<double> linear_at(const std::vector<float>& times, const std::vector<float>& values,
                              size_t width, double t) {
  size_t hi = 0;
  while (hi < times.size() && times[hi] <= t) ++hi;
  auto key = [&](size_t k) {
    return std::vector<double>(values.begin() + long(k * width),
                               values.begin() + long((k + 1) * width));
  };
  if (hi == 0) return key(0);
  if (hi == times.size()) return key(hi - 1);
  double u = (t - times[hi - 1]) / (times[hi] - times[hi - 1]);
  std::vector<double> a = key(hi - 1), b = key(hi);
  for (size_t i = 0; i < width; ++i) a[i] += (b[i] - a[i]) * u;
  return a;
}

glm::dmat4 column_major(const std::vector<float>& v, size_t matrix) {
  glm::dmat4 m;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) m[c][r] = v[16 * matrix + size_t(4 * c + r)];
  return m;
}

// SimpleSkin's vertices in the world at time t, by the specification's skinning equation.
std::vector<glm::dvec3> simple_skin_reference(const ReferenceGltf& f, double t) {
  const nlohmann::json& prim = f.json["meshes"][0]["primitives"][0];
  std::vector<float> positions = f.floats(prim["attributes"]["POSITION"]);
  std::vector<float> joints = f.floats(prim["attributes"]["JOINTS_0"]);
  std::vector<float> weights = f.floats(prim["attributes"]["WEIGHTS_0"]);
  std::vector<float> binds = f.floats(f.json["skins"][0]["inverseBindMatrices"]);
  const nlohmann::json& sampler = f.json["animations"][0]["samplers"][0];
  std::vector<float> times = f.floats(sampler["input"]), rotations = f.floats(sampler["output"]);
  EXPECT_EQ(f.json["animations"][0]["channels"][0]["target"]["node"], 2);

  // Node 1 (joint 0) has no transform; node 2 (joint 1), its child, is translated (0, 1, 0) and
  // rotated by the animation: glTF's (x, y, z, w) keys go into glm's (w, x, y, z), and LINEAR
  // rotations slerp between the two keys around t, as the spec says.
  const nlohmann::json& node2 = f.json["nodes"][2];
  size_t hi = 0;
  while (hi < times.size() && times[hi] <= t) ++hi;
  glm::dquat q;
  auto quat = [&](size_t k) {
    return glm::dquat(rotations[4 * k + 3], rotations[4 * k], rotations[4 * k + 1],
                      rotations[4 * k + 2]);
  };
  if (hi == 0)
    q = quat(0);
  else if (hi == times.size())
    q = quat(hi - 1);
  else
    q = glm::slerp(quat(hi - 1), quat(hi), (t - times[hi - 1]) / double(times[hi] - times[hi - 1]));
  glm::dmat4 joint0(1);
  glm::dmat4 joint1 =
      joint0 *
      glm::translate(glm::dmat4(1), glm::dvec3(node2["translation"][0], node2["translation"][1],
                                               node2["translation"][2])) *
      glm::mat4_cast(glm::normalize(q));
  glm::dmat4 world_of_joint[2] = {joint0, joint1};
  std::vector<glm::dvec3> out;
  for (size_t v = 0; v < positions.size() / 3; ++v) {
    glm::dvec4 p(positions[3 * v], positions[3 * v + 1], positions[3 * v + 2], 1);
    glm::dvec4 sum(0);
    for (size_t k = 0; k < 4; ++k) {
      size_t j = size_t(joints[4 * v + k]);
      sum += double(weights[4 * v + k]) * (world_of_joint[j] * column_major(binds, j) * p);
    }
    out.emplace_back(sum);
  }
  return out;
}

void expect_world_positions(const Scene& scene, const std::vector<glm::dvec3>& expected,
                            double tolerance, const std::string& what) {
  ASSERT_EQ(scene.instances.size(), 1u) << what;
  const Instance& instance = scene.instances[0];
  const Mesh& mesh = scene.meshes[instance.mesh];
  ASSERT_EQ(mesh.positions.size(), expected.size()) << what;
  for (size_t v = 0; v < expected.size(); ++v) {
    Point3f p = instance.world_from_object(mesh.positions[v]);
    EXPECT_NEAR(p.x, expected[v].x, tolerance) << what << " vertex " << v;
    EXPECT_NEAR(p.y, expected[v].y, tolerance) << what << " vertex " << v;
    EXPECT_NEAR(p.z, expected[v].z, tolerance) << what << " vertex " << v;
  }
}

TEST(GltfSkin, SimpleSkinVerticesMatchGlmAtEveryTime) {
  const std::string path = data_path("gltf/SimpleSkin/SimpleSkin.gltf");
  ReferenceGltf reference(path);
  for (double t : {0.0, 0.5, 1.0, 1.25, 2.0, 2.75, 3.5, 4.6, 5.5, 7.0}) {
    Scene scene = load_gltf(path, at_time(t));
    expect_world_positions(scene, simple_skin_reference(reference, t), 1e-5,
                           "t = " + std::to_string(t));
  }
}

TEST(GltfSkin, SimpleSkinBendsTheUpperHalf) {
  // A plain-number check beside the glm one: at t = 0 the skin is in its bind pose (the mesh's
  // own positions); when the animation has turned the upper joint, the top row has moved.
  const std::string path = data_path("gltf/SimpleSkin/SimpleSkin.gltf");
  ReferenceGltf reference(path);
  std::vector<float> bind = reference.floats(1);
  Scene rest = load_gltf(path, at_time(0));
  const Mesh& mesh = rest.meshes[rest.instances[0].mesh];
  for (size_t v = 0; v < mesh.positions.size(); ++v)
    EXPECT_NEAR(mesh.positions[v].y, bind[3 * v + 1], 1e-6) << v;
  Scene bent = load_gltf(path, at_time(1.0));
  const Mesh& moved = bent.meshes[bent.instances[0].mesh];
  // The bottom vertices (y = 0) are held by joint 0 alone and never move.
  for (size_t v = 0; v < moved.positions.size(); ++v)
    if (bind[3 * v + 1] == 0) {
      EXPECT_NEAR(moved.positions[v].x, bind[3 * v], 1e-6) << v;
      EXPECT_NEAR(moved.positions[v].y, 0, 1e-6) << v;
    }
}

TEST(GltfSkin, TheSkinnedNodesOwnTransformIsIgnored) {
  // The spec: only the joints place a skinned mesh. Moving node 0 (the mesh's node) by (5, 0, 0)
  // must not move a single vertex.
  const std::string path = data_path("gltf/SimpleSkin/SimpleSkin.gltf");
  ReferenceGltf reference(path);
  nlohmann::json doc = reference.json;
  doc["nodes"][0]["translation"] = {5.0, 0.0, 0.0};
  doc["nodes"][0]["scale"] = {2.0, 2.0, 2.0};
  std::string text = doc.dump();
  Scene scene =
      load_gltf_bytes(std::span(reinterpret_cast<const uint8_t*>(text.data()), text.size()),
                      "moved.gltf", data_path("gltf/SimpleSkin"), at_time(2.0));
  expect_world_positions(scene, simple_skin_reference(reference, 2.0), 1e-5, "moved mesh node");
}

TEST(GltfSkin, AnOpenShutterPosesTheSkinAtEvenTimesAcrossIt) {
  // The still pose at t = 1 s, and for motion blur the poses at 9 times from 0.95 to 1.05 s.
  const std::string path = data_path("gltf/SimpleSkin/SimpleSkin.gltf");
  ReferenceGltf reference(path);
  GltfLoadOptions options = at_time(1.0);
  options.exposure_s = 0.1;
  Scene scene = load_gltf(path, options);
  expect_world_positions(scene, simple_skin_reference(reference, 1.0), 1e-5, "still");
  const Mesh& mesh = scene.meshes[scene.instances[0].mesh];
  const MeshDeformation& d = mesh.deformation;
  EXPECT_DOUBLE_EQ(d.open_s, 0.95);
  EXPECT_DOUBLE_EQ(d.close_s, 1.05);
  ASSERT_EQ(d.positions.size(), 9u);
  for (size_t k = 0; k < d.positions.size(); ++k) {
    Scene step = scene;
    step.meshes[step.instances[0].mesh].positions = d.positions[k];
    expect_world_positions(step, simple_skin_reference(reference, 0.95 + 0.1 * double(k) / 8), 1e-5,
                           "step " + std::to_string(k));
  }
  // Past the animation's end (5.5 s) nothing moves: no deformation to blur.
  options.time_s = 8;
  Scene still = load_gltf(path, options);
  EXPECT_FALSE(still.meshes[still.instances[0].mesh].deforms());
}

TEST(GltfMorph, AnimatedMorphCubeBlendsTheTargetsByTheAnimatedWeights) {
  const std::string path = data_path("gltf/AnimatedMorphCube/AnimatedMorphCube.glb");
  ReferenceGltf f(path);
  const nlohmann::json& prim = f.json["meshes"][0]["primitives"][0];
  std::vector<float> base = f.floats(prim["attributes"]["POSITION"]);
  std::vector<float> base_normal = f.floats(prim["attributes"]["NORMAL"]);
  std::vector<float> d0 = f.floats(prim["targets"][0]["POSITION"]);
  std::vector<float> d1 = f.floats(prim["targets"][1]["POSITION"]);
  std::vector<float> n0 = f.floats(prim["targets"][0]["NORMAL"]);
  std::vector<float> n1 = f.floats(prim["targets"][1]["NORMAL"]);
  const nlohmann::json& sampler = f.json["animations"][0]["samplers"][0];
  std::vector<float> times = f.floats(sampler["input"]), weights = f.floats(sampler["output"]);
  ASSERT_EQ(weights.size(), 2 * times.size());
  const double between = 0.5 * (times[40] + times[41]);
  for (double t : {0.0, double(times[20]), between, 2.0, 3.3, 10.0}) {
    std::vector<double> w = linear_at(times, weights, 2, t);
    Scene scene = load_gltf(path, at_time(t));
    ASSERT_EQ(scene.instances.size(), 1u);
    const Mesh& mesh = scene.meshes[scene.instances[0].mesh];
    ASSERT_EQ(mesh.positions.size(), base.size() / 3);
    for (size_t v = 0; v < mesh.positions.size(); ++v)
      for (int c = 0; c < 3; ++c) {
        size_t i = 3 * v + size_t(c);
        EXPECT_NEAR(mesh.positions[v][c], base[i] + w[0] * d0[i] + w[1] * d1[i], 1e-7)
            << "t = " << t << " vertex " << v;
        glm::dvec3 n = glm::normalize(
            glm::dvec3(base_normal[3 * v] + w[0] * n0[3 * v] + w[1] * n1[3 * v],
                       base_normal[3 * v + 1] + w[0] * n0[3 * v + 1] + w[1] * n1[3 * v + 1],
                       base_normal[3 * v + 2] + w[0] * n0[3 * v + 2] + w[1] * n1[3 * v + 2]));
        EXPECT_NEAR(mesh.normals[v][c], n[c], 1e-5) << "t = " << t << " vertex " << v;
      }
  }
}

class GltfMorphWeights : public GltfHostile {
 protected:
  // The one-triangle file with one morph target whose POSITION deltas are the positions
  // themselves: weight w scales the triangle by 1 + w.
  json morphing_triangle() {
    json doc = triangle();
    doc["meshes"][0]["primitives"][0]["targets"] = {{{"POSITION", 0}}};
    return doc;
  }
  Point3f second_vertex(const json& doc) {  // (1, 0, 0) in the base shape
    Scene scene = load_gltf(write("morph.gltf", doc));
    return scene.meshes[scene.instances.at(0).mesh].positions.at(1);
  }
};

TEST_F(GltfMorphWeights, NodeWeightsOverrideMeshWeightsWhichDefaultToZero) {
  json doc = morphing_triangle();
  EXPECT_FLOAT_EQ(second_vertex(doc).x, 1);
  doc["meshes"][0]["weights"] = {0.5};
  EXPECT_FLOAT_EQ(second_vertex(doc).x, 1.5);
  doc["nodes"][0]["weights"] = {2.0};
  EXPECT_FLOAT_EQ(second_vertex(doc).x, 3);
}

TEST_F(GltfMorphWeights, StaticWeightsDoNotMotionBlur) {
  json doc = morphing_triangle();
  doc["meshes"][0]["weights"] = {0.5};
  GltfLoadOptions options;
  options.exposure_s = 1.0 / 60;
  Scene scene = load_gltf(write("static-morph.gltf", doc), options);
  EXPECT_FALSE(scene.meshes[scene.instances.at(0).mesh].deforms());
}

TEST_F(GltfMorphWeights, MismatchedTargetCountIsAnError) {
  json doc = morphing_triangle();
  doc["accessors"].push_back({{"bufferView", 2},
                              {"byteOffset", 64},
                              {"componentType", 5126},
                              {"count", 2},
                              {"type", "VEC3"}});
  doc["meshes"][0]["primitives"][0]["targets"][0]["POSITION"] = 2;
  doc["meshes"][0]["weights"] = {1.0};  // targets are read when a weight uses them
  expect_error(doc, "short-target.gltf",
               {"meshes[0].primitives[0].targets[0].POSITION", "2 elements for 3 positions"});
}

TEST_F(GltfMorphWeights, JointsOutsideTheSkinAreAnError) {
  json doc = triangle();
  // JOINTS_0 names joint 3 of a one-joint skin, with weight 1.
  std::vector<uint8_t> bytes = buffer_bytes();
  const uint8_t joints[12] = {3, 0, 0, 0, 3, 0, 0, 0, 3, 0, 0, 0};
  const float weights[12] = {1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0};
  std::memcpy(bytes.data() + 64, joints, sizeof joints);
  std::memcpy(bytes.data() + 128, weights, sizeof weights);
  set_buffer(doc, bytes);
  int j = add_accessor(doc, {{"bufferView", 2},
                             {"byteOffset", 64},
                             {"componentType", 5121},
                             {"count", 3},
                             {"type", "VEC4"}});
  int w = add_accessor(doc, {{"bufferView", 2},
                             {"byteOffset", 128},
                             {"componentType", 5126},
                             {"count", 3},
                             {"type", "VEC4"}});
  int m = add_accessor(doc, {{"bufferView", 2},
                             {"byteOffset", 192},
                             {"componentType", 5126},
                             {"count", 1},
                             {"type", "MAT4"}});
  doc["meshes"][0]["primitives"][0]["attributes"]["JOINTS_0"] = j;
  doc["meshes"][0]["primitives"][0]["attributes"]["WEIGHTS_0"] = w;
  doc["nodes"][0]["skin"] = 0;
  doc["nodes"].push_back(json::object());
  doc["skins"] = {{{"joints", {1}}, {"inverseBindMatrices", m}}};
  expect_error(doc, "bad-joint.gltf", {"JOINTS_0", "names joint 3 but the skin has 1"});
}

}  // namespace
}  // namespace obscura::test
