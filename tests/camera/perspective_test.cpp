// Field of view from focal length and sensor, against published values, and Blender's sensor
// fit rules.
#include "obscura/camera/perspective.h"

#include <gtest/gtest.h>

#include "obscura/camera/camera.h"
#include "obscura/math/error.h"

namespace obscura {
namespace {

Camera camera_with(Perspective p, int width, int height) {
  Camera c;
  c.projection = p;
  c.film.width_px = width;
  c.film.height_px = height;
  return c;
}

// Horizontal angles of view of 50, 35 and 24 mm lenses on a 36 mm-wide (full-frame) sensor, as
// lens makers publish them: 39.5978°, 54.4322°, 73.7398°.
TEST(Perspective, HorizontalFieldOfViewOfFullFrameLenses) {
  struct Case {
    double focal_length_mm, expected_degrees;
  } cases[] = {{50, 39.5978}, {35, 54.4322}, {24, 73.7398}};
  for (const Case& k : cases) {
    Perspective p;
    p.focal_length_mm = k.focal_length_mm;
    Camera c = camera_with(p, 3000, 2000);  // a 3:2 image fills the 36 × 24 mm sensor
    EXPECT_NEAR(c.fov_degrees().x, k.expected_degrees, 5e-5) << k.focal_length_mm << " mm";
    EXPECT_NEAR(fov_degrees(36, k.focal_length_mm), k.expected_degrees, 5e-5);
  }
}

TEST(Perspective, FieldOfViewRoundTripsThroughFocalLength) {
  EXPECT_NEAR(focal_length_mm_for_fov(39.5978, 36), 50, 1e-4);
  Perspective v = Perspective::from_vertical_fov_degrees(39.307648, 25);
  EXPECT_NEAR(v.focal_length_mm, 35, 1e-5);  // the Cornell box camera: 35 mm on 25 mm film
}

// Blender: AUTO fits sensor_width to the larger image dimension; HORIZONTAL to the width;
// VERTICAL sensor_height to the height.
TEST(Perspective, SensorFitFollowsBlender) {
  Perspective p;  // 50 mm, 36 × 24
  // Landscape 2:1, auto → width spans 36 mm: film 36 × 18.
  Vector2d landscape = film_size_mm(p, 2.0);
  EXPECT_DOUBLE_EQ(landscape.x, 36);
  EXPECT_DOUBLE_EQ(landscape.y, 18);
  // Portrait 1:2, auto → height spans sensor_width 36 mm: film 18 × 36.
  Vector2d portrait = film_size_mm(p, 0.5);
  EXPECT_DOUBLE_EQ(portrait.x, 18);
  EXPECT_DOUBLE_EQ(portrait.y, 36);
  p.sensor_fit = SensorFit::vertical;  // height spans 24 mm whatever the aspect
  EXPECT_DOUBLE_EQ(film_size_mm(p, 2.0).y, 24);
  EXPECT_DOUBLE_EQ(film_size_mm(p, 2.0).x, 48);
  p.sensor_fit = SensorFit::horizontal;
  EXPECT_DOUBLE_EQ(film_size_mm(p, 0.5).x, 36);
  EXPECT_DOUBLE_EQ(film_size_mm(p, 0.5).y, 72);
}

TEST(Perspective, VerticalFovIsKeptAtAnyAspect) {
  for (auto [w, h] : {std::pair{512, 512}, std::pair{800, 200}, std::pair{200, 800}}) {
    Camera c = camera_with(Perspective::from_vertical_fov_degrees(45), w, h);
    EXPECT_NEAR(c.fov_degrees().y, 45, 1e-9) << w << "x" << h;
  }
  Camera c = camera_with(Perspective::from_horizontal_fov_degrees(90), 300, 900);
  EXPECT_NEAR(c.fov_degrees().x, 90, 1e-9);
}

TEST(Perspective, PixelAspectWidensTheImage) {
  // 100 × 100 pixels twice as wide as tall: the image is 2:1 on the sensor.
  Camera c = camera_with(Perspective::from_vertical_fov_degrees(60), 100, 100);
  c.film.pixel_aspect = 2;
  double tan_y = std::tan(30 * 3.14159265358979323846 / 180);
  EXPECT_NEAR(std::tan(c.fov_degrees().x * 3.14159265358979323846 / 360), 2 * tan_y, 1e-12);
}

TEST(Perspective, RejectsBadParametersNamingThem) {
  auto expect_error = [](auto make, const std::string& fragment) {
    try {
      make();
      ADD_FAILURE() << "no error for " << fragment;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    }
  };
  expect_error([] { Perspective::from_vertical_fov_degrees(0); }, "vertical_fov_degrees");
  expect_error([] { Perspective::from_vertical_fov_degrees(180); }, "180");
  expect_error([] { Perspective::from_horizontal_fov_degrees(-5); }, "-5");
  expect_error(
      [] {
        Perspective p;
        p.focal_length_mm = 0;
        validate(p);
      },
      "focal_length_mm");
  expect_error(
      [] {
        Perspective p;
        p.sensor_width_mm = -36;
        validate(p);
      },
      "sensor_width_mm: must be positive; got -36");
  expect_error(
      [] {
        Perspective p;
        p.sensor_height_mm = 0;
        validate(p);
      },
      "sensor_height_mm");
}

}  // namespace
}  // namespace obscura
