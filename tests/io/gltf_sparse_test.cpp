// Sparse accessors (glTF 2.0 §3.6.2.5): substitutions applied to the dense elements, and
// validated like them.
#include <cstring>

#include "gltf_hostile.h"

namespace obscura::test {
namespace {

class GltfSparse : public GltfHostile {
 protected:
  // The one-triangle file whose POSITION accessor moves vertex 2 from (0, 1, 0) to (0, 2, 0)
  // through a sparse substitution: one UNSIGNED_BYTE index at byte 100, its VEC3 at byte 104.
  json sparse_triangle(uint8_t target_index, int count = 1) {
    std::vector<uint8_t> bytes = buffer_bytes();
    bytes[100] = target_index;
    bytes[101] = 1;  // a second index, used when count = 2
    const float moved[3] = {0, 2, 0};
    std::memcpy(bytes.data() + 104, moved, sizeof moved);
    json doc = triangle();
    doc["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64(bytes);
    doc["accessors"][0]["sparse"] = {
        {"count", count},
        {"indices", {{"bufferView", 2}, {"byteOffset", 100}, {"componentType", 5121}}},
        {"values", {{"bufferView", 2}, {"byteOffset", 104}}}};
    return doc;
  }
};

TEST_F(GltfSparse, SubstitutesTheNamedElements) {
  Scene scene = load_gltf(write("sparse.gltf", sparse_triangle(2)));
  ASSERT_EQ(scene.meshes.size(), 1u);
  const std::vector<Point3f>& p = scene.meshes[0].positions;
  ASSERT_EQ(p.size(), 3u);
  EXPECT_EQ(p[0], Point3f(0, 0, 0));
  EXPECT_EQ(p[1], Point3f(1, 0, 0));
  EXPECT_EQ(p[2], Point3f(0, 2, 0));
}

TEST_F(GltfSparse, BadSubstitutionsAreErrorsNamingTheAccessor) {
  expect_error(write("past.gltf", sparse_triangle(3)), {"sparse.indices", "not below the count 3"});
  // Indices 2 then 1: not increasing.
  expect_error(write("order.gltf", sparse_triangle(2, 2)), {"sparse.indices", "not increasing"});
  json too_many = sparse_triangle(2, 4);
  expect_error(write("count.gltf", too_many), {"sparse", "count 4"});
  json outside = sparse_triangle(2);
  outside["accessors"][0]["sparse"]["values"]["byteOffset"] = 640;
  expect_error(write("outside.gltf", outside), {"sparse.values", "exceed bufferView 2"});
}

}  // namespace
}  // namespace obscura::test
