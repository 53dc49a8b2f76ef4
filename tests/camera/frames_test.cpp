// Frames: Z-up to Y-up conversion and look-at.
#include "obscura/camera/frames.h"

#include <gtest/gtest.h>

#include "obscura/math/error.h"

namespace obscura {
namespace {

TEST(Frames, ZUpBecomesYUpAsBlendersGltfExporterDoes) {
  Transform t = y_up_from(UpAxis::z);
  // Blender (Z-up, −Y towards the viewer of the front view) → glTF (Y-up, +Z towards the viewer).
  Point3d up = t(Point3d(0, 0, 1)), forward = t(Point3d(0, 1, 0)), right = t(Point3d(1, 0, 0));
  EXPECT_EQ(up, Point3d(0, 1, 0));
  EXPECT_EQ(forward, Point3d(0, 0, -1));
  EXPECT_EQ(right, Point3d(1, 0, 0));
  EXPECT_FALSE(t.swaps_handedness());
  EXPECT_EQ(y_up_from(UpAxis::y), Transform());
  EXPECT_EQ(parse_up_axis("Z"), UpAxis::z);
  EXPECT_THROW(parse_up_axis("x"), Error);
}

TEST(Frames, LookAtPutsTheCameraAtTheEyeFacingTheTarget) {
  Transform world_from_camera = world_from_camera_look_at({1, 2, 3}, {1, 2, -7});
  EXPECT_EQ(world_from_camera(Point3d(0, 0, 0)), Point3d(1, 2, 3));
  Vector3d forward = world_from_camera(Vector3d(0, 0, -1));
  EXPECT_NEAR(forward.z, -1, 1e-15);
  EXPECT_THROW(world_from_camera_look_at({0, 0, 0}, {0, 5, 0}, {0, 1, 0}), Error);
}

}  // namespace
}  // namespace obscura
