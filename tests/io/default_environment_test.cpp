// Which scenes count as bringing their own light, and what each --environment choice sets.
#include "obscura/io/default_environment.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <numbers>

#include "obscura/io/scene_loader.h"
#include "obscura/math/error.h"
#include "obscura/scene/shapes.h"

namespace obscura {
namespace {

constexpr double kPi = std::numbers::pi;

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

// A grey 1 m box lit only by two 2 cm square lamps of radiance 5 (a lantern's bulbs).
Scene box_with_small_lamps() {
  Scene scene;
  scene.materials = {diffuse_material("grey", Rgb(0.5f)),
                     diffuse_material("bulb", Rgb(0.f), Rgb(5.f))};
  Mesh box = make_box({1, 1, 1});
  box.material = 0;
  scene.add_mesh(std::move(box));
  for (float x : {-0.2f, 0.2f}) {
    Mesh lamp = make_rectangle(0.02f, 0.02f);
    lamp.material = 1;
    scene.add_mesh(std::move(lamp), Transform::translate({x, 0.51, 0}));
  }
  return scene;
}

TEST(DefaultEnvironment, EmittedPowerIsMeasuredAgainstTheSurround) {
  const Scene scene = box_with_small_lamps();
  const EmitterLight light = emitter_light(scene);
  EXPECT_EQ(light.emitters, 2u);
  // π · L · A per lamp, by hand; the surround's 4π²R² over the bounds' half diagonal.
  const double power = 2 * kPi * 5 * 0.02 * 0.02;
  EXPECT_NEAR(light.power_w, power, 1e-6);
  const Bounds3f b = scene.bounds();
  const double r = 0.5 * distance(b.min, b.max);
  EXPECT_NEAR(light.relative, power / (4 * kPi * kPi * r * r), 1e-8);
}

TEST(DefaultEnvironment, EmittersTooFaintToSeeByGetTheEnvironmentToo) {
  Scene faint = box_with_small_lamps();
  apply_environment(faint, parse_environment_choice("auto"));
  ASSERT_TRUE(faint.environment);
  ASSERT_EQ(faint.warnings.size(), 1u);
  EXPECT_NE(faint.warnings[0].find("2 emissive surface(s)"), std::string::npos)
      << faint.warnings[0];
  EXPECT_NE(faint.warnings[0].find("--environment none"), std::string::npos);
  // Asked for, their own light alone.
  Scene own = box_with_small_lamps();
  apply_environment(own, parse_environment_choice("none"));
  EXPECT_FALSE(own.environment);

  // The measured Cornell box is lit by its ceiling light alone, as published.
  Scene cornell = load_scene("cornell-box");
  const double relative = emitter_light(cornell).relative;
  std::printf("the Cornell box's light: %.4f of the surround's\n", relative);
  EXPECT_GT(relative, 3 * kFaintEmitterLight);
  apply_environment(cornell, parse_environment_choice("auto"));
  EXPECT_FALSE(cornell.environment);
  // A lamp as large as the scene, likewise.
  Scene bright = one_triangle(diffuse_material("lamp", Rgb(0.5f), Rgb(10.f)));
  apply_environment(bright, parse_environment_choice("auto"));
  EXPECT_FALSE(bright.environment);
}

}  // namespace
}  // namespace obscura
