// Orthographic: parallel rays perpendicular to the film, sizes independent of depth.
#include "obscura/camera/orthographic.h"

#include <gtest/gtest.h>

#include "obscura/camera/camera.h"
#include "obscura/camera/frames.h"
#include "obscura/math/error.h"

namespace obscura {
namespace {

Camera ortho_camera() {
  Camera c;
  c.projection = Orthographic{.view_height_m = 2, .view_width_m = std::nullopt};
  c.film.width_px = 300;
  c.film.height_px = 200;
  c.world_from_camera = world_from_camera_look_at({1, 2, 3}, {0, 0, 0});
  return c;
}

TEST(Orthographic, EveryRayHasTheSameDirection) {
  Camera c = ortho_camera();
  Vector3d forward = normalize(Vector3d(-1, -2, -3));
  for (Point2d film : {Point2d(0, 0), Point2d(300, 200), Point2d(17.5, 150.25)}) {
    auto ray = c.generate_ray(film);
    ASSERT_TRUE(ray);
    EXPECT_NEAR(ray->direction.x, forward.x, 1e-12);
    EXPECT_NEAR(ray->direction.y, forward.y, 1e-12);
    EXPECT_NEAR(ray->direction.z, forward.z, 1e-12);
  }
}

TEST(Orthographic, SizeOnFilmDoesNotChangeWithDepth) {
  Camera c = ortho_camera();
  c.world_from_camera = Transform();
  // A 0.5 m bar across the view at depths 1, 5 and 20 m covers 0.5 m × (200 px / 2 m) = 50 px.
  for (double depth : {1.0, 5.0, 20.0}) {
    auto a = c.project({-0.25, 0.1, -depth});
    auto b = c.project({0.25, 0.1, -depth});
    ASSERT_TRUE(a && b);
    EXPECT_NEAR(b->film_point.x - a->film_point.x, 50, 1e-9);
    EXPECT_NEAR(a->film_point.y, 100 - 0.1 * 100, 1e-9);
  }
}

TEST(Orthographic, ViewWidthFollowsTheImageAspectUnlessGiven) {
  Camera c = ortho_camera();
  ScreenWindow w = c.screen_window();
  EXPECT_DOUBLE_EQ(w.x_max - w.x_min, 3);  // 2 m × 300/200
  c.projection = Orthographic{.view_height_m = 2, .view_width_m = 5};
  w = c.screen_window();
  EXPECT_DOUBLE_EQ(w.x_max - w.x_min, 5);
}

TEST(Orthographic, RejectsBadParametersNamingThem) {
  Camera c = ortho_camera();
  c.projection = Orthographic{.view_height_m = 0, .view_width_m = std::nullopt};
  EXPECT_THROW(c.validate(), Error);
  c.projection = Orthographic{.view_height_m = 1, .view_width_m = -2};
  try {
    c.validate();
    ADD_FAILURE();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("view_width_m"), std::string::npos);
  }
  // A near plane at 0 is fine for parallel projection, not below.
  c.projection = Orthographic{};
  c.near_m = 0;
  EXPECT_NO_THROW(c.validate());
  c.near_m = -1;
  EXPECT_THROW(c.validate(), Error);
}

}  // namespace
}  // namespace obscura
