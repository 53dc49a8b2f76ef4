// KHR_draco_mesh_compression: a known grid encoded with Draco's own encoder in the test, loaded
// back and compared with the original within the quantization chosen here; corrupted streams
// and accessors that disagree with the stream are clear errors.
#include <draco/compression/encode.h>
#include <draco/mesh/mesh.h>

#include "gltf_hostile.h"
#include "gltf_known_grid.h"

namespace obscura::test {
namespace {

// Quantization bits and the largest error each allows over the grid's extent: a quantized
// coordinate is within half a step of range / (2^bits − 1) of the original.
constexpr int kPositionBits = 14, kNormalBits = 10, kUvBits = 12;
constexpr float kPositionError = 4.0f / ((1 << kPositionBits) - 1);  // range 4 (x and y)
constexpr float kUvError = 1.0f / ((1 << kUvBits) - 1);
// Draco's octahedral normals: about 2 / 2^bits per component, doubled for safety.
constexpr float kNormalError = 4.0f / (1 << kNormalBits);

class GltfDraco : public GltfHostile {
 public:
  KnownGrid grid;

  // The grid as a Draco stream; attribute unique ids 0 POSITION, 1 NORMAL, 2 TEX_COORD.
  std::vector<uint8_t> encoded() const {
    draco::Mesh mesh;
    const auto n = uint32_t(grid.vertex_count());
    mesh.set_num_points(n);
    auto add = [&](draco::GeometryAttribute::Type type, int components,
                   const std::vector<float>& values) {
      draco::GeometryAttribute attribute;
      attribute.Init(type, nullptr, uint8_t(components), draco::DT_FLOAT32, false,
                     int64_t(sizeof(float)) * components, 0);
      int id = mesh.AddAttribute(attribute, true, n);
      for (uint32_t v = 0; v < n; ++v)
        mesh.attribute(id)->SetAttributeValue(draco::AttributeValueIndex(v),
                                              &values[size_t(v) * size_t(components)]);
      return id;
    };
    EXPECT_EQ(add(draco::GeometryAttribute::POSITION, 3, grid.positions), 0);
    EXPECT_EQ(add(draco::GeometryAttribute::NORMAL, 3, grid.normals), 1);
    EXPECT_EQ(add(draco::GeometryAttribute::TEX_COORD, 2, grid.uvs), 2);
    for (size_t t = 0; t < grid.indices.size() / 3; ++t)
      mesh.AddFace({draco::PointIndex(grid.indices[3 * t]),
                    draco::PointIndex(grid.indices[3 * t + 1]),
                    draco::PointIndex(grid.indices[3 * t + 2])});
    draco::Encoder encoder;
    encoder.SetAttributeQuantization(draco::GeometryAttribute::POSITION, kPositionBits);
    encoder.SetAttributeQuantization(draco::GeometryAttribute::NORMAL, kNormalBits);
    encoder.SetAttributeQuantization(draco::GeometryAttribute::TEX_COORD, kUvBits);
    draco::EncoderBuffer buffer;
    draco::Status status = encoder.EncodeMeshToBuffer(mesh, &buffer);
    EXPECT_TRUE(status.ok()) << status.error_msg_string();
    return std::vector<uint8_t>(buffer.data(), buffer.data() + buffer.size());
  }

  // A file whose one primitive is `stream`; accessors 0–2 the attributes (no bufferView: the
  // data lives only in the stream), accessor 3 the UNSIGNED_SHORT indices.
  json document(const std::vector<uint8_t>& stream) const {
    const auto n = grid.vertex_count();
    auto floats = [&](const char* type) {
      return json{{"componentType", 5126}, {"count", n}, {"type", type}};
    };
    return {
        {"asset", {{"version", "2.0"}}},
        {"extensionsUsed", {"KHR_draco_mesh_compression"}},
        {"extensionsRequired", {"KHR_draco_mesh_compression"}},
        {"scenes", {{{"nodes", {0}}}}},
        {"nodes", {{{"mesh", 0}}}},
        {"meshes",
         {{{"primitives",
            {{{"attributes", {{"POSITION", 0}, {"NORMAL", 1}, {"TEXCOORD_0", 2}}},
              {"indices", 3},
              {"extensions",
               {{"KHR_draco_mesh_compression",
                 {{"bufferView", 0},
                  {"attributes", {{"POSITION", 0}, {"NORMAL", 1}, {"TEXCOORD_0", 2}}}}}}}}}}}}},
        {"buffers",
         {{{"byteLength", stream.size()},
           {"uri", "data:application/octet-stream;base64," + base64(stream)}}}},
        {"bufferViews", {{{"buffer", 0}, {"byteLength", stream.size()}}}},
        {"accessors",
         {floats("VEC3"),
          floats("VEC3"),
          floats("VEC2"),
          {{"componentType", 5123}, {"count", grid.indices.size()}, {"type", "SCALAR"}}}},
    };
  }
};

TEST_F(GltfDraco, DecodesPositionsNormalsUvsAndIndicesWithinTheQuantization) {
  Scene scene = load_gltf(write("draco.gltf", document(encoded())));
  ASSERT_EQ(scene.meshes.size(), 1u);
  grid.expect_same(scene.meshes[0], kPositionError, kNormalError, kUvError);
  EXPECT_FALSE(has_warning(scene, "KHR_draco_mesh_compression"));
}

TEST_F(GltfDraco, AccessorsMayAskForQuantizedComponentTypes) {
  // KHR_mesh_quantization with Draco: normalized UNSIGNED_SHORT uvs, UNSIGNED_INT indices.
  json doc = document(encoded());
  doc["accessors"][2]["componentType"] = 5123;
  doc["accessors"][2]["normalized"] = true;
  doc["accessors"][3]["componentType"] = 5125;
  Scene scene = load_gltf(write("quantized.gltf", doc));
  ASSERT_EQ(scene.meshes.size(), 1u);
  grid.expect_same(scene.meshes[0], kPositionError, kNormalError, kUvError + 1.f / 65535);
}

TEST_F(GltfDraco, AccessorsThatDisagreeWithTheStreamAreErrors) {
  const std::vector<uint8_t> stream = encoded();
  json doc = document(stream);
  doc["accessors"][0]["count"] = grid.vertex_count() + 1;
  expect_error(doc, "count.gltf",
               {"count.gltf", "meshes[0].primitives[0].attributes.POSITION",
                "count 26 differs from the Draco mesh's 25 points"});
  doc = document(stream);
  doc["accessors"][3]["count"] = 3;
  expect_error(doc, "indices.gltf",
               {"meshes[0].primitives[0].indices", "count 3 differs from the 96 indices"});
  doc = document(stream);
  doc["accessors"][3]["componentType"] = 5121;  // UNSIGNED_BYTE holds the 25 vertices...
  EXPECT_NO_THROW(load_gltf(write("byte.gltf", doc)));
  doc = document(stream);
  doc["accessors"][0]["type"] = "VEC2";
  expect_error(doc, "vec2.gltf", {"attributes.POSITION", "3 components per element"});
  doc = document(stream);
  doc["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"]["attributes"]
     ["NORMAL"] = 7;
  expect_error(doc, "id.gltf", {"attributes.NORMAL", "no attribute with id 7"});
  doc = document(stream);
  doc["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"]["bufferView"] = 4;
  expect_error(doc, "view.gltf", {"view.gltf", "invalid bufferView"});  // tinygltf's words
}

TEST_F(GltfDraco, TruncatedOrCorruptStreamsAreErrorsNotCrashes) {
  const std::vector<uint8_t> stream = encoded();
  for (size_t keep : {size_t(1), size_t(4), stream.size() / 2, stream.size() - 1}) {
    std::vector<uint8_t> cut(stream.data(), stream.data() + keep);
    expect_error(document(cut), "cut" + std::to_string(keep) + ".gltf",
                 {"KHR_draco_mesh_compression", "Draco"});
  }
  // Flipped bytes anywhere: a clear error or (when the damage lands in values) a mesh.
  for (size_t at = 0; at < stream.size(); at += 3) {
    std::vector<uint8_t> bad = stream;
    bad[at] ^= 0x5a;
    try {
      load_gltf(write("flip.gltf", document(bad)));
    } catch (const Error& e) {
      EXPECT_THAT(e.what(), testing::HasSubstr("flip.gltf")) << "byte " << at;
    }
  }
}

}  // namespace
}  // namespace obscura::test
