// The views of a dataset (render/dataset_views.h) and camera placement
// (render/camera_placement.h): orbit and sphere views look at the centre of the scene's bounds
// from the distance that frames them, deterministically; a path starts and ends at its keys.
#include "obscura/render/dataset_views.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "obscura/io/scene_loader.h"
#include "obscura/math/request_error.h"
#include "obscura/render/camera_placement.h"
#include "run_command.h"

namespace obscura {
namespace {

Point3d centre_of(const Scene& scene) {
  const Point3f c = scene.bounds().center();
  return {c.x, c.y, c.z};
}

Point3d eye_of(const Camera& camera) {
  return camera.world_from_camera.at(0)(Point3d(0, 0, 0));
}

TEST(DatasetViews, OrbitAndSphereFrameTheBoundsLookingAtTheirCentre) {
  const Scene scene = load_scene("cornell-box");
  const CameraRequest request;
  for (const char* spec : {"orbit:12", "orbit:5:-30", "sphere:24"}) {
    SCOPED_TRACE(spec);
    const std::vector<DatasetView> views = dataset_views(scene, request, spec, 64, 48);
    const Vector3f d = scene.bounds().diagonal();
    const double radius =
        0.5 * std::sqrt(double(d.x) * d.x + double(d.y) * d.y + double(d.z) * d.z);
    const Vector2d fov = views[0].camera.fov_degrees();
    const double distance =
        radius / std::sin(std::min(fov.x, fov.y) / 2 * 3.14159265358979323846 / 180) * 1.05;
    for (size_t i = 0; i < views.size(); ++i) {
      EXPECT_EQ(views[i].name, dataset_view_name(i));
      EXPECT_NEAR(obscura::distance(eye_of(views[i].camera), centre_of(scene)), distance, 1e-9);
      // The centre lands on the image centre.
      auto at = views[i].camera.project(centre_of(scene));
      ASSERT_TRUE(at);
      EXPECT_NEAR(at->film_point.x, 32, 1e-9);
      EXPECT_NEAR(at->film_point.y, 24, 1e-9);
    }
    // Deterministic, to the bit.
    const std::vector<DatasetView> again = dataset_views(scene, request, spec, 64, 48);
    for (size_t i = 0; i < views.size(); ++i)
      EXPECT_EQ(views[i].camera.world_from_camera.at(0), again[i].camera.world_from_camera.at(0));
  }
  // orbit: view 0 in front (+Z), at 20 degrees elevation.
  const auto orbit = dataset_views(scene, request, "orbit:4", 64, 48);
  const Vector3d first = normalize(eye_of(orbit[0].camera) - centre_of(scene));
  EXPECT_NEAR(first.x, 0, 1e-12);
  EXPECT_NEAR(first.y, std::sin(20 * 3.14159265358979323846 / 180), 1e-12);
  EXPECT_GT(first.z, 0);
}

TEST(DatasetViews, APathRunsThroughItsKeyframes) {
  const std::string file = test::make_temp_dir("path") + "/path.txt";
  std::ofstream(file) << "0 0 5  0 0 0\n4 0 5  4 0 0  # a comment\n4 0 9 4 0 4\n";
  const auto views = dataset_views(load_scene("cornell-box"), CameraRequest{}, "path:5:" + file);
  ASSERT_EQ(views.size(), 5u);
  const Point3d expected[] = {{0, 0, 5}, {2, 0, 5}, {4, 0, 5}, {4, 0, 7}, {4, 0, 9}};
  for (size_t i = 0; i < 5; ++i)
    EXPECT_NEAR(obscura::distance(eye_of(views[i].camera), expected[i]), 0, 1e-12) << i;
}

TEST(CameraPlacement, PositionLookAtAndUp) {
  const Transform start = Transform::translate({1, 2, 3});
  // A position alone moves the camera and keeps its orientation.
  Transform moved = placed_pose(start, {.position = Point3d(0, 0, 9)});
  EXPECT_EQ(moved(Point3d(0, 0, 0)), Point3d(0, 0, 9));
  EXPECT_EQ(moved(Vector3d(0, 0, -1)), Vector3d(0, 0, -1));
  // Looking straight down without an up: the camera's own up is used.
  Transform down = placed_pose(start, {.look_at = Point3d(1, -5, 3)});
  EXPECT_NEAR(down(Vector3d(0, 0, -1)).y, -1, 1e-12);
  EXPECT_NEAR(down(Vector3d(0, 1, 0)).z, -1, 1e-12);
  // An up alone rolls the camera about its view direction.
  Transform rolled = placed_pose(start, {.up = Vector3d(1, 0, 0)});
  EXPECT_NEAR(rolled(Vector3d(0, 1, 0)).x, 1, 1e-12);
  EXPECT_NEAR(rolled(Vector3d(0, 0, -1)).z, -1, 1e-12);
  EXPECT_THROW(placed_pose(start, {.look_at = Point3d(1, 2, 3)}), RequestError);
  EXPECT_THROW(placed_pose(start, {.look_at = Point3d(1, 9, 3), .up = Vector3d(0, 2, 0)}),
               RequestError);
  EXPECT_THROW(placed_pose(start, {.position = Point3d(NAN, 0, 0)}), RequestError);
}

}  // namespace
}  // namespace obscura
