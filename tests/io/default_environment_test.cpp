// Which scenes count as bringing their own light, and what each --environment choice sets.
#include "obscura/io/default_environment.h"

#include <gtest/gtest.h>

#include "obscura/math/error.h"

namespace obscura {
namespace {

Scene one_triangle(Material material) {
  Scene scene;
  Mesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  mesh.indices = {0, 1, 2};
  mesh.material = 0;
  scene.meshes.push_back(mesh);
  Instance instance;
  instance.mesh = 0;
  scene.instances.push_back(instance);
  scene.materials.push_back(std::move(material));
  return scene;
}

TEST(DefaultEnvironment, WhatCountsAsTheScenesOwnLight) {
  EXPECT_FALSE(scene_has_own_light(one_triangle(diffuse_material("grey", Rgb(0.5f)))));
  // An untextured emitter is an area light (the Cornell box's ceiling light).
  EXPECT_TRUE(scene_has_own_light(one_triangle(diffuse_material("lamp", Rgb(0.5f), Rgb(10.f)))));
  // Textured emission (a screen, a label) is decoration.
  Material screen = diffuse_material("screen", Rgb(0.5f), Rgb(1.f));
  screen.emission_texture.texture = 0;
  EXPECT_FALSE(scene_has_own_light(one_triangle(screen)));
  Scene lit = one_triangle(diffuse_material("grey", Rgb(0.5f)));
  lit.lights.push_back(Light{"bulb", PointLight{}});
  EXPECT_TRUE(scene_has_own_light(lit));
  Scene with_sky = one_triangle(diffuse_material("grey", Rgb(0.5f)));
  with_sky.environment = Environment{};
  EXPECT_TRUE(scene_has_own_light(with_sky));
}

TEST(DefaultEnvironment, ChoicesSetOrClearTheEnvironment) {
  Scene scene = one_triangle(diffuse_material("grey", Rgb(0.5f)));
  apply_environment(scene, parse_environment_choice("white"));
  ASSERT_TRUE(scene.environment);
  EXPECT_EQ(scene.environment->texture, -1);
  EXPECT_EQ(scene.environment->color * scene.environment->intensity, Rgb(1.f));
  // auto keeps an environment the scene already has.
  apply_environment(scene, parse_environment_choice("auto"));
  EXPECT_EQ(scene.environment->texture, -1);
  EXPECT_TRUE(scene.warnings.empty());
  apply_environment(scene, parse_environment_choice("none"));
  EXPECT_FALSE(scene.environment);
  EXPECT_THROW(apply_environment(scene, parse_environment_choice("/no/such/map.exr")), Error);
  EXPECT_THROW(parse_environment_choice(""), Error);
}

}  // namespace
}  // namespace obscura
