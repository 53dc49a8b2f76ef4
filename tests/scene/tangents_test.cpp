// Generated tangents on quads whose UV layout fixes T, B and the handedness by hand: T is the
// direction in which u grows, and the bitangent w · cross(N, T) the direction in which v falls
// (glTF's v runs down the image; a normal map's +Y is up).
#include "obscura/scene/tangents.h"

#include <gtest/gtest.h>

namespace obscura {
namespace {

// The unit square in the z = 0 plane, normals +z, corners counter-clockwise from (0, 0).
Mesh square(std::vector<Point2f> uvs) {
  Mesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  m.normals.assign(4, Normal3f(0, 0, 1));
  m.indices = {0, 1, 2, 0, 2, 3};
  m.uvs = std::move(uvs);
  return m;
}

void expect_frame(const std::vector<Vector4f>& tangents, Vector3f t, float w, Vector3f bitangent) {
  ASSERT_EQ(tangents.size(), 4u);
  for (const Vector4f& g : tangents) {
    EXPECT_NEAR(g.x, t.x, 1e-6f);
    EXPECT_NEAR(g.y, t.y, 1e-6f);
    EXPECT_NEAR(g.z, t.z, 1e-6f);
    EXPECT_EQ(g.w, w);
    Vector3f b = cross(Vector3f(0, 0, 1), Vector3f(g.x, g.y, g.z)) * g.w;
    EXPECT_NEAR(b.x, bitangent.x, 1e-6f);
    EXPECT_NEAR(b.y, bitangent.y, 1e-6f);
    EXPECT_NEAR(b.z, bitangent.z, 1e-6f);
  }
}

TEST(Tangents, AnImageLaidFlatHasTangentAlongUAndBitangentUpTheImage) {
  // The image's top-left corner (UV 0, 0) at (0, 1): u grows along +x, v along −y.
  Mesh m = square({{0, 1}, {1, 1}, {1, 0}, {0, 0}});
  expect_frame(generate_tangents(m, 0), {1, 0, 0}, 1, {0, 1, 0});
}

TEST(Tangents, AMirroredLayoutGetsNegativeHandedness) {
  // The same image flipped left to right: u grows along −x, v still along −y.
  Mesh m = square({{1, 1}, {0, 1}, {0, 0}, {1, 0}});
  expect_frame(generate_tangents(m, 0), {-1, 0, 0}, -1, {0, 1, 0});
}

TEST(Tangents, AVerticallyMirroredLayoutToo) {
  // Flipped top to bottom: u along +x, v along +y, so the image's up is −y.
  Mesh m = square({{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  expect_frame(generate_tangents(m, 0), {1, 0, 0}, -1, {0, -1, 0});
}

TEST(Tangents, ARotatedAndStretchedLayoutFollowsU) {
  // The image turned a quarter and stretched: u = 2y grows along +y, v = 3x along +x.
  Mesh m = square({{0, 0}, {0, 3}, {2, 3}, {2, 0}});
  expect_frame(generate_tangents(m, 0), {0, 1, 0}, 1, {-1, 0, 0});
}

TEST(Tangents, AreOrthogonalisedAgainstTheVertexNormal) {
  Mesh m = square({{0, 1}, {1, 1}, {1, 0}, {0, 0}});
  m.normals.assign(4, Normal3f(0.6f, 0, 0.8f));  // tilted towards +x
  std::vector<Vector4f> t = generate_tangents(m, 0);
  ASSERT_EQ(t.size(), 4u);
  for (const Vector4f& g : t) {  // (1, 0, 0) − 0.6·n, normalized
    EXPECT_NEAR(g.x, 0.8f, 1e-6f);
    EXPECT_NEAR(g.y, 0, 1e-6f);
    EXPECT_NEAR(g.z, -0.6f, 1e-6f);
    EXPECT_EQ(g.w, 1);
  }
}

TEST(Tangents, FollowTheRequestedUvSet) {
  Mesh m = square({{0, 1}, {1, 1}, {1, 0}, {0, 0}});
  m.uvs1 = {{1, 1}, {0, 1}, {0, 0}, {1, 0}};  // the mirrored layout
  expect_frame(generate_tangents(m, 0), {1, 0, 0}, 1, {0, 1, 0});
  expect_frame(generate_tangents(m, 1), {-1, 0, 0}, -1, {0, 1, 0});
  EXPECT_TRUE(generate_tangents(m, 2).empty());  // a set the mesh does not have
  m.uvs.clear();
  EXPECT_TRUE(generate_tangents(m, 0).empty());
}

TEST(Tangents, DegenerateUvsStillGiveAUnitTangentInThePlane) {
  Mesh m = square({{0.5f, 0.5f}, {0.5f, 0.5f}, {0.5f, 0.5f}, {0.5f, 0.5f}});
  for (const Vector4f& g : generate_tangents(m, 0)) {
    EXPECT_NEAR(g.x * g.x + g.y * g.y + g.z * g.z, 1, 1e-5f);
    EXPECT_NEAR(g.z, 0, 1e-6f);
    EXPECT_EQ(std::abs(g.w), 1);
  }
}

TEST(Tangents, AMeshWithoutNormalsUsesItsFaces) {
  Mesh m = square({{0, 1}, {1, 1}, {1, 0}, {0, 0}});
  m.normals.clear();
  expect_frame(generate_tangents(m, 0), {1, 0, 0}, 1, {0, 1, 0});
}

}  // namespace
}  // namespace obscura
