// KHR_texture_transform, checked against the Khronos TextureTransformTest sample
// (tests/data/gltf/TextureTransformTest, CC0): the sample places a "correct" marker where the
// arrow of each transformed quad must point, and "not supported" / "error" markers where it
// points when the transform is ignored or applied the wrong way round. The expected directions
// come from those marker positions in the file, not from the transform's formula.
#include <gtest/gtest.h>

#include <cmath>
#include <variant>

#include "obscura/io/gltf_loader.h"
#include "obscura/scene/scene.h"
#include "obscura/scene/texture.h"
#include "test_paths.h"

namespace obscura {
namespace {

const Material& material_named(const Scene& scene, const std::string& name) {
  for (const Material& m : scene.materials)
    if (m.name == name) return m;
  throw std::runtime_error("no material " + name);
}

const TextureRef& base_color(const Scene& scene, const std::string& name) {
  return std::get<MetallicRoughnessMaterial>(material_named(scene, name).model).base_color_texture;
}

Scene transform_test() {
  return load_gltf(test::data_path("gltf/TextureTransformTest/TextureTransformTest.gltf"));
}

TEST(GltfTextureTransform, IdentityByDefault) {
  UvTransform t;
  EXPECT_TRUE(t.is_identity());
  Point2f p = t({0.25f, 0.75f});
  EXPECT_EQ(p.x, 0.25f);
  EXPECT_EQ(p.y, 0.75f);
}

TEST(GltfTextureTransform, OffsetsShiftTheLookup) {
  Scene scene = transform_test();
  // The top row: UVs (0, 0)..(0.5, 0.5) shifted by (0.5, 0), (0, 0.5) and (0.5, 0.5).
  struct Case {
    const char* name;
    float du, dv;
  };
  for (Case c :
       {Case{"Offset U", 0.5f, 0}, Case{"Offset V", 0, 0.5f}, Case{"Offset UV", 0.5f, 0.5f}}) {
    const TextureRef& ref = base_color(scene, c.name);
    ASSERT_TRUE(ref.valid()) << c.name;
    Point2f p = ref.transform({0.1f, 0.2f});
    EXPECT_NEAR(p.x, 0.1f + c.du, 1e-6f) << c.name;
    EXPECT_NEAR(p.y, 0.2f + c.dv, 1e-6f) << c.name;
  }
}

// The marker nodes are children of the quad's node, in its local frame, where the quad spans
// [-0.5, 0.5]² and UV (0, 0) is its top-left corner (v grows downwards). A marker at local (x, y)
// therefore sits at UV (x + 0.5, 0.5 - y).
Point2f marker_uv(double x, double y) {
  return {float(x + 0.5), float(0.5 - y)};
}

// The arrow in Arrow.png runs from the UV origin along the diagonal u = v.
double angle_from_diagonal(Point2f uv) {
  return std::atan2(double(uv.y), double(uv.x)) - std::atan2(1.0, 1.0);
}

TEST(GltfTextureTransform, RotationPointsTheArrowAtTheCorrectMarker) {
  Scene scene = transform_test();
  const TextureRef& ref = base_color(scene, "Rotation");
  ASSERT_TRUE(ref.valid());
  // Node "Rotation - Correct" at (-0.0790, -0.5163), "Rotation - Error" at (0.5163, 0.0790).
  Point2f correct = ref.transform(marker_uv(-0.07904822439840126, -0.5162674857624154));
  Point2f error = ref.transform(marker_uv(0.5162674857624154, 0.07904822439840126));
  EXPECT_NEAR(angle_from_diagonal(correct), 0, 1e-5);
  EXPECT_GT(std::abs(angle_from_diagonal(error)), 0.7);  // 45° off the other way
}

TEST(GltfTextureTransform, ScaleAndTheCombinedTransformHitTheirMarkers) {
  Scene scene = transform_test();
  // The rotation quad's markers sit 1.1 from the UV origin, so the arrow's tip is at texture UV
  // (1.1/√2, 1.1/√2). The "Scale - Correct" (0.0185, -0.0185) and "All - Correct" (-0.07, -0.25)
  // markers must map onto that tip.
  const float tip = float(1.1 / std::sqrt(2.0));
  Point2f s =
      base_color(scene, "Scale").transform(marker_uv(0.018544972870134853, -0.018544972870134853));
  EXPECT_NEAR(s.x, tip, 1e-4f);
  EXPECT_NEAR(s.y, tip, 1e-4f);
  // The sample places this marker by eye: within 0.04 of the tip (ignoring the rotation would
  // put it 0.4 away, rotating the wrong way 0.9).
  Point2f a = base_color(scene, "All").transform(marker_uv(-0.07, -0.25));
  EXPECT_LT(std::hypot(a.x - tip, a.y - tip), 0.04f);
  EXPECT_LT(std::abs(angle_from_diagonal(a)), 0.05);
}

TEST(GltfTextureTransform, TexturesWithoutTheExtensionKeepTheIdentity) {
  Scene scene = transform_test();
  EXPECT_TRUE(base_color(scene, "Correct").transform.is_identity());
  EXPECT_TRUE(base_color(scene, "Error").transform.is_identity());
}

}  // namespace
}  // namespace obscura
