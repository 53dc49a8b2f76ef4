// The scene's bookkeeping: instanced counts, world bounds through instance transforms, and
// validation that names what is wrong.
#include "obscura/scene/scene.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "obscura/math/error.h"
#include "obscura/scene/builtin_scenes.h"
#include "obscura/scene/shapes.h"

namespace obscura {
namespace {

Scene two_boxes() {
  Scene s;
  s.name = "boxes";
  s.materials.resize(2);
  s.materials[1].emission = Rgb(1.f);
  s.add_mesh(make_box({1, 1, 1}), Transform::translate({10, 0, 0}));
  Instance second = s.instances[0];
  second.world_from_object = Transform::translate({-10, 0, 0}) * Transform::scale(2, 2, 2);
  second.material = 1;
  s.instances.push_back(second);
  return s;
}

TEST(Scene, CountsInstancesAndStoredGeometrySeparately) {
  SceneStats st = two_boxes().stats();
  EXPECT_EQ(st.triangles, 24u);
  EXPECT_EQ(st.unique_triangles, 12u);
  EXPECT_EQ(st.vertices, 24u);
  EXPECT_EQ(st.instances, 2u);
  EXPECT_EQ(st.emissive_meshes, 1u);  // the second instance overrides its material
  EXPECT_GT(st.memory_bytes, 24 * sizeof(Point3f));
}

TEST(Scene, BoundsApplyInstanceTransforms) {
  Bounds3f b = two_boxes().bounds();
  EXPECT_FLOAT_EQ(b.min.x, -11);  // the scaled box spans −10 ± 1
  EXPECT_FLOAT_EQ(b.max.x, 10.5f);
  EXPECT_FLOAT_EQ(b.max.y, 1);
}

TEST(Scene, ValidationNamesTheProblem) {
  auto expect = [](Scene s, const char* fragment) {
    try {
      s.validate();
      ADD_FAILURE() << "no error: " << fragment;
    } catch (const Error& e) {
      EXPECT_THAT(e.what(), testing::HasSubstr(fragment));
    }
  };
  Scene s = two_boxes();
  EXPECT_NO_THROW(s.validate());
  Scene bad = s;
  bad.meshes[0].indices[4] = 99;
  expect(bad, "index 4 = 99 is past the vertex count 24");
  bad = s;
  bad.meshes[0].positions[3].y = std::nanf("");
  expect(bad, "vertex 3 position is not finite");
  bad = s;
  bad.instances[1].material = 5;
  expect(bad, "material index 5 is past the material count 2");
  bad = s;
  bad.instances[0].mesh = 3;
  expect(bad, "mesh index 3 is past the mesh count 1");
  bad = s;
  bad.meshes[0].normals.pop_back();
  expect(bad, "normals has 23 entries for 24 vertices");
  bad = s;
  bad.materials[0].model =
      DiffuseMaterial{.reflectance = Rgb(0.5f), .reflectance_texture = {.texture = 0, .uv_set = 0}};
  expect(bad, "reflectance texture index 0 is past the texture count 0");
}

TEST(Scene, MaterialTypeNamesAreTheFileFormatNames) {
  EXPECT_EQ(material_type_name(DiffuseMaterial{}), "diffuse");
  EXPECT_EQ(material_type_name(PhongMaterial{}), "phong");
  EXPECT_EQ(material_type_name(ConductorMaterial{}), "conductor");
  EXPECT_EQ(material_type_name(DielectricMaterial{}), "dielectric");
  EXPECT_EQ(material_type_name(MetallicRoughnessMaterial{}), "metallic-roughness");
  EXPECT_EQ(material_type_name(EmissiveMaterial{}), "emissive");
}

TEST(Scene, CornellBoxHasThePublishedDimensions) {
  // Cornell's published data: 16 quads (32 triangles), floor 552.8 × 559.2 mm, ceiling at
  // 548.8 mm, one emissive quad (the light, 130 × 105 mm).
  Scene box = make_cornell_box();
  EXPECT_EQ(box.stats().triangles, 32u);
  EXPECT_EQ(box.stats().emissive_meshes, 1u);
  Bounds3f b = box.bounds();
  EXPECT_NEAR(b.max.y, 0.5488f, 1e-6);
  EXPECT_NEAR(b.max.z, 0.5592f, 1e-6);
  ASSERT_EQ(box.cameras.size(), 1u);
  EXPECT_NEAR(box.camera.fov_degrees().y, 2 * std::atan(12.5 / 35) * 180 / 3.141592653589793, 1e-5);
}

}  // namespace
}  // namespace obscura
