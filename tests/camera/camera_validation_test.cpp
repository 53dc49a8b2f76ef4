// Bad camera input gets a clear error naming the parameter and its value.
#include <string>

#include <gtest/gtest.h>

#include "obscura/camera/camera.h"
#include "obscura/math/error.h"

namespace obscura {
namespace {

std::string validation_message(const Camera& c) {
  try {
    c.validate();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(CameraValidation, DefaultCameraIsValid) {
  EXPECT_EQ(validation_message(Camera{}), "");
}

TEST(CameraValidation, NamesTheParameterAndItsValue) {
  struct Case {
    const char* what;
    void (*break_it)(Camera&);
    const char* expected;
  } cases[] = {
      {"focal length", [](Camera& c) { std::get<Perspective>(c.projection).focal_length_mm = -1; },
       "camera.focal_length_mm: must be positive; got -1"},
      {"sensor", [](Camera& c) { std::get<Perspective>(c.projection).sensor_width_mm = 0; },
       "camera.sensor_width_mm: must be positive; got 0"},
      {"near zero", [](Camera& c) { c.near_m = 0; }, "camera.near_m: must be positive; got 0"},
      {"near negative", [](Camera& c) { c.near_m = -0.5; }, "camera.near_m"},
      {"near ≥ far", [](Camera& c) { c.far_m = c.near_m; }, "camera.far_m: must exceed near"},
      {"f-number", [](Camera& c) { c.lens.f_number = 0; },
       "camera.f_number: must be positive; got 0"},
      {"focus", [](Camera& c) { c.lens.focus_distance_m = -3; },
       "camera.focus_distance_m: must be positive; got -3"},
      {"resolution", [](Camera& c) { c.film.height_px = 0; }, "camera.resolution"},
      {"crop", [](Camera& c) { c.film.crop.x_max = 2; }, "camera.crop: must lie within [0, 1]"},
      {"shutter", [](Camera& c) { c.shutter = {.open_s = 1, .close_s = 0}; }, "camera.shutter"},
      {"depth of field needs perspective",
       [](Camera& c) {
         c.projection = Orthographic{};
         c.lens.depth_of_field = true;
       },
       "camera.depth_of_field"},
  };
  for (const Case& k : cases) {
    Camera c;
    k.break_it(c);
    std::string message = validation_message(c);
    EXPECT_NE(message.find(k.expected), std::string::npos) << k.what << ": got '" << message << "'";
  }
}

}  // namespace
}  // namespace obscura
