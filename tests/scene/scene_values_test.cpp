// The scene's side of the value contract (math/value_limits.h): coordinates beyond ±1e7 m and
// light values beyond 1e12 are refused by Scene::validate, naming the field, before any renderer
// (or Embree, which aborts on |coordinates| > ~1.8e18) sees them.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "obscura/math/error.h"
#include "obscura/scene/scene.h"
#include "obscura/scene/shapes.h"

namespace obscura {
namespace {

using ::testing::HasSubstr;

Scene one_floor() {
  Scene s;
  s.name = "values";
  s.materials.push_back(diffuse_material("grey", Rgb(0.5f)));
  Mesh floor = make_rectangle(4, 4);
  floor.name = "floor";
  s.add_mesh(std::move(floor));
  s.lights.push_back({.name = "bulb", .model = PointLight{.position = {0, 2, 0}}});
  return s;
}

std::string refusal(const std::function<void(Scene&)>& change) {
  Scene s = one_floor();
  change(s);
  try {
    s.validate();
  } catch (const Error& e) {
    return e.what();
  }
  return "(accepted)";
}

TEST(SceneValues, AnOrdinarySceneAndOneAtTheBoundAreAccepted) {
  EXPECT_NO_THROW(one_floor().validate());
  Scene far = one_floor();
  far.instances[0].world_from_object = Transform::translate({9.9e6, 0, -9.9e6});
  std::get<PointLight>(far.lights[0].model).position = {0, 9.9e6f, 0};
  EXPECT_NO_THROW(far.validate());
}

TEST(SceneValues, InstancesBeyondTheCoordinateBoundAreRefused) {
  EXPECT_THAT(refusal([](Scene& s) {
                s.instances[0].world_from_object = Transform::scale(1e18, 1e18, 1e18);
              }),
              AllOf(HasSubstr("instance 'floor'"), HasSubstr("world_from_object"),
                    HasSubstr("single-precision")));
  EXPECT_THAT(refusal([](Scene& s) {
                s.instances[0].world_from_object = Transform::translate({-1e308, 0, 0});
              }),
              AllOf(HasSubstr("instance 'floor'"), HasSubstr("-1e+308")));
  EXPECT_THAT(refusal([](Scene& s) {
                s.instances[0].motion = {{0, Transform()}, {1, Transform::translate({0, 2e7, 0})}};
              }),
              AllOf(HasSubstr("instance 'floor'"), HasSubstr("motion key 1")));
}

TEST(SceneValues, LightsOutOfRangeAreRefusedByField) {
  EXPECT_THAT(refusal([](Scene& s) {
                std::get<PointLight>(s.lights[0].model).position = {1e30f, 0, 0};
              }),
              AllOf(HasSubstr("light 'bulb'"), HasSubstr("position")));
  EXPECT_THAT(
      refusal([](Scene& s) { std::get<PointLight>(s.lights[0].model).intensity = Rgb(1e38f); }),
      AllOf(HasSubstr("light 'bulb'"), HasSubstr("intensity")));
  EXPECT_THAT(
      refusal([](Scene& s) {
        s.lights.push_back({.name = "sun", .model = DirectionalLight{.direction = {0, 0, 0}}});
      }),
      AllOf(HasSubstr("light 'sun'"), HasSubstr("direction")));
  EXPECT_THAT(refusal([](Scene& s) {
                SpotLight spot;
                spot.intensity = Rgb(-1.f);
                s.lights.push_back({.name = "spot", .model = spot});
              }),
              AllOf(HasSubstr("light 'spot'"), HasSubstr("intensity")));
}

TEST(SceneValues, EmissionStrengthAndEnvironmentBeyondTheBoundAreRefused) {
  // glTF's KHR_materials_emissive_strength is unbounded: 1e38 made the light's power inf.
  EXPECT_THAT(refusal([](Scene& s) { s.materials[0].emission = Rgb(1e38f); }),
              AllOf(HasSubstr("material 'grey'"), HasSubstr("emission")));
  EXPECT_THAT(refusal([](Scene& s) { s.environment.emplace().intensity = 1e30f; }),
              AllOf(HasSubstr("environment"), HasSubstr("intensity")));
  EXPECT_THAT(refusal([](Scene& s) { s.environment.emplace().color = Rgb(-1.f); }),
              HasSubstr("environment"));
}

}  // namespace
}  // namespace obscura
