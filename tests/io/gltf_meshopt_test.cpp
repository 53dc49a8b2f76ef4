// EXT_meshopt_compression: the known grid encoded with meshoptimizer's own encoders in the test
// (positions lossless, normals through the OCTAHEDRAL filter, uvs through EXPONENTIAL, indices
// as TRIANGLES or INDICES), its fallback buffer left out, loaded from .gltf and .glb and
// compared with the original; damaged data and fields are clear errors.
#include <meshoptimizer.h>

#include "gltf_hostile.h"
#include "gltf_known_grid.h"

namespace obscura::test {
namespace {

constexpr int kNormalBits = 8;  // octahedral x/y in 8-bit normalized bytes
constexpr int kUvBits = 15;     // exponential filter: a shared exponent, 15-bit mantissas
// An 8-bit octahedral encoding is within about 2 / 127 per component (two steps of the grid).
constexpr float kNormalError = 2.f / 127;
constexpr float kUvError = 1.f / (1 << kUvBits);  // relative to |uv| ≤ 1

class GltfMeshopt : public GltfHostile {
 public:
  KnownGrid grid;
  std::vector<uint8_t> compressed;  // buffer 0: every compressed stream, one after another
  json views = json::array();       // bufferViews 0–3: positions, normals, uvs, indices
  uint64_t fallback_bytes = 0;      // buffer 1's length: the uncompressed views, packed

  // Appends `data` (count × stride bytes) compressed in `mode` with `filter`, and its view.
  void add_view(const std::vector<uint8_t>& data, size_t count, size_t stride,
                const std::string& mode, const std::string& filter) {
    std::vector<uint8_t> out;
    if (mode == "ATTRIBUTES") {
      out.resize(meshopt_encodeVertexBufferBound(count, stride));
      out.resize(meshopt_encodeVertexBuffer(out.data(), out.size(), data.data(), count, stride));
    } else {
      std::vector<uint32_t> indices(count);
      for (size_t i = 0; i < count; ++i)
        indices[i] = stride == 2 ? uint32_t(data[2 * i] | data[2 * i + 1] << 8)
                                 : uint32_t(data[4 * i] | data[4 * i + 1] << 8);
      size_t vertices = grid.vertex_count();
      if (mode == "TRIANGLES") {
        out.resize(meshopt_encodeIndexBufferBound(count, vertices));
        out.resize(meshopt_encodeIndexBuffer(out.data(), out.size(), indices.data(), count));
      } else {
        out.resize(meshopt_encodeIndexSequenceBound(count, vertices));
        out.resize(meshopt_encodeIndexSequence(out.data(), out.size(), indices.data(), count));
      }
    }
    ASSERT_FALSE(out.empty());
    json ext = {{"buffer", 0},
                {"byteOffset", compressed.size()},
                {"byteLength", out.size()},
                {"byteStride", stride},
                {"count", count},
                {"mode", mode}};
    if (filter != "NONE") ext["filter"] = filter;
    json view = {{"buffer", 1},
                 {"byteOffset", fallback_bytes},
                 {"byteLength", count * stride},
                 {"extensions", {{"EXT_meshopt_compression", ext}}}};
    if (mode == "ATTRIBUTES") view["byteStride"] = stride;
    views.push_back(view);
    compressed.insert(compressed.end(), out.begin(), out.end());
    while (compressed.size() % 4) compressed.push_back(0);
    fallback_bytes += count * stride;
  }

  // The grid with `index_mode` TRIANGLES (UNSIGNED_SHORT) or INDICES (UNSIGNED_INT).
  json document(const std::string& index_mode = "TRIANGLES") {
    const size_t n = grid.vertex_count();
    std::vector<uint8_t> positions(n * 12);
    std::memcpy(positions.data(), grid.positions.data(), positions.size());
    add_view(positions, n, 12, "ATTRIBUTES", "NONE");
    std::vector<float> normals4;  // the filter takes x, y, z, w per vector
    for (size_t v = 0; v < n; ++v)
      normals4.insert(normals4.end(),
                      {grid.normals[3 * v], grid.normals[3 * v + 1], grid.normals[3 * v + 2], 0.f});
    std::vector<uint8_t> normals(n * 4);
    meshopt_encodeFilterOct(normals.data(), n, 4, kNormalBits, normals4.data());
    add_view(normals, n, 4, "ATTRIBUTES", "OCTAHEDRAL");
    std::vector<uint8_t> uvs(n * 8);
    meshopt_encodeFilterExp(uvs.data(), n, 8, kUvBits, grid.uvs.data());
    add_view(uvs, n, 8, "ATTRIBUTES", "EXPONENTIAL");
    size_t index_size = index_mode == "TRIANGLES" ? 2 : 4;
    std::vector<uint8_t> indices(grid.indices.size() * index_size);
    for (size_t i = 0; i < grid.indices.size(); ++i)
      if (index_size == 2) {
        uint16_t v = uint16_t(grid.indices[i]);
        std::memcpy(&indices[2 * i], &v, 2);
      } else {
        std::memcpy(&indices[4 * i], &grid.indices[i], 4);
      }
    add_view(indices, grid.indices.size(), index_size, index_mode, "NONE");
    return {
        {"asset", {{"version", "2.0"}}},
        {"extensionsUsed", {"EXT_meshopt_compression", "KHR_mesh_quantization"}},
        {"extensionsRequired", {"EXT_meshopt_compression", "KHR_mesh_quantization"}},
        {"scenes", {{{"nodes", {0}}}}},
        {"nodes", {{{"mesh", 0}}}},
        {"meshes",
         {{{"primitives",
            {{{"attributes", {{"POSITION", 0}, {"NORMAL", 1}, {"TEXCOORD_0", 2}}},
              {"indices", 3}}}}}}},
        {"buffers",
         {{{"byteLength", compressed.size()},
           {"uri", "data:application/octet-stream;base64," + base64(compressed)}},
          {{"byteLength", fallback_bytes},
           {"extensions", {{"EXT_meshopt_compression", {{"fallback", true}}}}}}}},
        {"bufferViews", views},
        {"accessors",
         {{{"bufferView", 0}, {"componentType", 5126}, {"count", n}, {"type", "VEC3"}},
          {{"bufferView", 1},
           {"componentType", 5120},
           {"normalized", true},
           {"count", n},
           {"type", "VEC3"}},
          {{"bufferView", 2}, {"componentType", 5126}, {"count", n}, {"type", "VEC2"}},
          {{"bufferView", 3},
           {"componentType", index_size == 2 ? 5123 : 5125},
           {"count", grid.indices.size()},
           {"type", "SCALAR"}}}},
    };
  }

  // A GLB whose BIN chunk is buffer 0 (the compressed streams).
  std::string glb(json doc) const {
    doc["buffers"][0].erase("uri");
    std::string text = doc.dump();
    while (text.size() % 4) text += ' ';
    std::string out = "glTF";
    auto u32 = [&](uint32_t v) { out.append(reinterpret_cast<const char*>(&v), 4); };
    u32(2);
    u32(uint32_t(12 + 8 + text.size() + 8 + compressed.size()));
    u32(uint32_t(text.size()));
    u32(0x4E4F534A);  // "JSON"
    out += text;
    u32(uint32_t(compressed.size()));
    u32(0x004E4942);  // "BIN"
    out.append(reinterpret_cast<const char*>(compressed.data()), compressed.size());
    return out;
  }
};

TEST_F(GltfMeshopt, DecodesFilteredAttributesAndTriangleIndicesWithoutFallbackData) {
  json doc = document("TRIANGLES");
  Scene scene = load_gltf(write("meshopt.gltf", doc));
  ASSERT_EQ(scene.meshes.size(), 1u);
  grid.expect_same(scene.meshes[0], 0.f, kNormalError, kUvError);  // positions: lossless
  Scene binary = load_gltf(write("meshopt.glb", glb(doc)));
  ASSERT_EQ(binary.meshes.size(), 1u);
  grid.expect_same(binary.meshes[0], 0.f, kNormalError, kUvError);
}

TEST_F(GltfMeshopt, DecodesIndexSequences) {
  Scene scene = load_gltf(write("sequence.gltf", document("INDICES")));
  ASSERT_EQ(scene.meshes.size(), 1u);
  grid.expect_same(scene.meshes[0], 0.f, kNormalError, kUvError);
  EXPECT_EQ(scene.meshes[0].indices, grid.indices);  // a sequence keeps the order exactly
}

TEST_F(GltfMeshopt, DamagedDataAndFieldsAreClearErrors) {
  json doc = document();
  json& positions = doc["bufferViews"][0]["extensions"]["EXT_meshopt_compression"];
  positions["byteLength"] = positions["byteLength"].get<int>() - 8;  // truncated stream
  expect_error(doc, "cut.gltf",
               {"cut.gltf", "bufferViews[0].extensions.EXT_meshopt_compression",
                "does not decode to 25 elements"});
  doc = document();
  doc["bufferViews"][3]["extensions"]["EXT_meshopt_compression"]["count"] = 99;
  expect_error(doc, "count.gltf", {"bufferViews[3]", "count"});
  doc = document();
  doc["bufferViews"][0]["extensions"]["EXT_meshopt_compression"]["mode"] = "VERTICES";
  expect_error(doc, "mode.gltf", {"mode", "'VERTICES' is not ATTRIBUTES, TRIANGLES or INDICES"});
  doc = document();
  doc["bufferViews"][0]["extensions"]["EXT_meshopt_compression"]["filter"] = "QUATERNION";
  expect_error(doc, "quat.gltf", {"byteStride", "12 must be 8 for filter QUATERNION"});
  doc = document();
  doc["bufferViews"][0]["extensions"]["EXT_meshopt_compression"]["buffer"] = 5;
  expect_error(doc, "buffer.gltf", {"buffer 5 is out of range"});
  // A forged count over a few bytes: refused before anything that size is allocated.
  doc = document();
  json& huge = doc["bufferViews"][0]["extensions"]["EXT_meshopt_compression"];
  huge["count"] = 2147483647;  // × 256 bytes = 512 GiB
  huge["byteStride"] = 256;
  doc["bufferViews"][0].erase("byteStride");  // (tinygltf caps a view's stride at 252)
  expect_error(doc, "huge.gltf", {"huge.gltf", "decompresses to more than 1024 MiB"});
  // An uncompressed view reading the left-out fallback buffer.
  doc = document();
  doc["bufferViews"][0].erase("extensions");
  expect_error(doc, "plain.gltf", {"bufferViews[0]", "fallback buffer whose data the file"});
  // Flipped bytes anywhere: a clear error or (when the damage lands in values) a mesh.
  doc = document();
  for (size_t at = 0; at < compressed.size(); at += 11) {
    std::vector<uint8_t> bad = compressed;
    bad[at] ^= 0xa5;
    json flipped = doc;
    flipped["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64(bad);
    try {
      load_gltf(write("flip.gltf", flipped));
    } catch (const Error& e) {
      EXPECT_THAT(e.what(), testing::HasSubstr("flip.gltf")) << "byte " << at;
    }
  }
}

}  // namespace
}  // namespace obscura::test
