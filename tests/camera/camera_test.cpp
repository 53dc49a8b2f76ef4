// The camera against answers worked by hand and against glm (an independent implementation of
// OpenGL's matrices): projection, corners, matrices, unproject.
#include "obscura/camera/camera.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "obscura/camera/frames.h"

namespace obscura {
namespace {

constexpr double kPi = std::numbers::pi;

Camera perspective_camera(Perspective p, int width, int height) {
  Camera c;
  c.projection = p;
  c.film.width_px = width;
  c.film.height_px = height;
  return c;
}

void expect_matrix_near(const Matrix4& ours, const glm::dmat4& theirs, double tolerance) {
  for (int row = 0; row < 4; ++row)
    for (int col = 0; col < 4; ++col)
      EXPECT_NEAR(ours[row][col], theirs[col][row], tolerance) << "row " << row << " col " << col;
}

// Camera at the origin looking down −Z, vertical FOV 90° (tan = 1) on a 200 × 100 film: the
// pinhole maps (x, y, z) to raster (W/2 + h·x/−z, H/2 − h·y/−z) with h = (H/2)/tan(45°) = 50.
TEST(Camera, ProjectsKnownPointsLikeThePinholeFormulaWorkedByHand) {
  Camera c = perspective_camera(Perspective::from_vertical_fov_degrees(90), 200, 100);
  struct Case {
    Point3d p;
    Point2d raster;
  } cases[] = {
      {{1, 0.5, -2}, {125, 37.5}},  // 100 + 50·0.5, 50 − 50·0.25
      {{0, 0, -3}, {100, 50}},      // on the axis: the centre
      {{-4, -1, -4}, {50, 62.5}},   // 100 − 50·1, 50 + 50·0.25
      {{2, 1, -1}, {200, 0}},       // the top-right corner of the frustum
  };
  for (const Case& k : cases) {
    auto projected = c.project(k.p);
    ASSERT_TRUE(projected) << k.p.x << "," << k.p.y << "," << k.p.z;
    EXPECT_NEAR(projected->film_point.x, k.raster.x, 1e-9);
    EXPECT_NEAR(projected->film_point.y, k.raster.y, 1e-9);
    EXPECT_NEAR(projected->depth_m, -k.p.z, 1e-12);
  }
  // 50 mm on a 36 × 24 mm sensor at 360 × 240: f in pixels = 50 · 360 / 36 = 500.
  Camera photo = perspective_camera(Perspective{}, 360, 240);
  auto p = photo.project({0.1, 0.2, -2});
  ASSERT_TRUE(p);
  EXPECT_NEAR(p->film_point.x, 180 + 500 * 0.05, 1e-9);
  EXPECT_NEAR(p->film_point.y, 120 - 500 * 0.1, 1e-9);
}

TEST(Camera, FilmCornersMapToTheFrustumCorners) {
  // x = (2·xp − W)/W · tan(fov_x/2), y = (H − 2·yp)/H · tan(fov_y/2) with the FOVs of a 35 mm lens
  // on 36 × 24 mm: tan(fov_x/2) = 18/35, tan(fov_y/2) = 12/35.
  Perspective lens;
  lens.focal_length_mm = 35;
  Camera c = perspective_camera(lens, 600, 400);
  double tx = 18.0 / 35, ty = 12.0 / 35;
  for (Point2d corner : {Point2d(0, 0), Point2d(600, 400), Point2d(600, 0), Point2d(0, 400)}) {
    auto ray = c.generate_ray(corner);
    ASSERT_TRUE(ray);
    Vector3d expected =
        normalize(Vector3d((2 * corner.x - 600) / 600 * tx, (400 - 2 * corner.y) / 400 * ty, -1));
    EXPECT_NEAR(ray->direction.x, expected.x, 1e-12);
    EXPECT_NEAR(ray->direction.y, expected.y, 1e-12);
    EXPECT_NEAR(ray->direction.z, expected.z, 1e-12);
  }
}

TEST(Camera, ProjectionMatrixEqualsGlmPerspective) {
  double fovy = 50, near = 0.25, far = 80;
  Camera c = perspective_camera(Perspective::from_vertical_fov_degrees(fovy), 640, 360);
  c.near_m = near;
  c.far_m = far;
  glm::dmat4 reference = glm::perspective(fovy * kPi / 180, 640.0 / 360.0, near, far);
  expect_matrix_near(c.projection_matrix(), reference, 1e-12);
  // Non-square pixels widen the physical aspect; glm takes it as the aspect argument.
  c.film.pixel_aspect = 1.25;
  reference = glm::perspective(fovy * kPi / 180, 640.0 * 1.25 / 360.0, near, far);
  expect_matrix_near(c.projection_matrix(), reference, 1e-12);
}

TEST(Camera, ShiftedLensMatchesGlmFrustum) {
  Perspective p;  // 50 mm, 36 × 24, fit auto → horizontal at 3:2
  p.lens_shift = {0.1, -0.2};
  Camera c = perspective_camera(p, 300, 200);
  c.near_m = 0.5;
  c.far_m = 20;
  // Film 36 × 24 mm; shift in units of the fitted width 36 mm: (3.6, −7.2) mm. On the near plane
  // the window is (mm / 50) · 0.5.
  double s = 0.5 / 50;
  glm::dmat4 reference =
      glm::frustum((3.6 - 18) * s, (3.6 + 18) * s, (-7.2 - 12) * s, (-7.2 + 12) * s, 0.5, 20.0);
  expect_matrix_near(c.projection_matrix(), reference, 1e-12);
}

TEST(Camera, InfiniteFarPlaneMatchesGlmInfinitePerspective) {
  Camera c = perspective_camera(Perspective::from_vertical_fov_degrees(60), 400, 300);
  c.near_m = 0.1;
  c.far_m = std::numeric_limits<double>::infinity();
  glm::dmat4 reference = glm::infinitePerspective(60 * kPi / 180, 400.0 / 300.0, 0.1);
  expect_matrix_near(c.projection_matrix(), reference, 1e-12);
}

TEST(Camera, OrthographicMatrixEqualsGlmOrtho) {
  Camera c;
  c.projection = Orthographic{.view_height_m = 3, .view_width_m = std::nullopt};
  c.film.width_px = 400;
  c.film.height_px = 200;
  c.near_m = 0.5;
  c.far_m = 40;
  glm::dmat4 reference = glm::ortho(-3.0, 3.0, -1.5, 1.5, 0.5, 40.0);
  expect_matrix_near(c.projection_matrix(), reference, 1e-12);
}

TEST(Camera, ViewMatrixEqualsGlmLookAt) {
  Point3d eye(1, 2, 3), target(-2, 0.5, -1);
  Vector3d up(0.1, 1, 0);
  Camera c;
  c.world_from_camera = world_from_camera_look_at(eye, target, up);
  glm::dmat4 reference =
      glm::lookAt(glm::dvec3(1, 2, 3), glm::dvec3(-2, 0.5, -1), glm::dvec3(0.1, 1, 0));
  expect_matrix_near(c.view_matrix(), reference, 1e-12);
}

TEST(Camera, MatricesPutPointsWhereProjectDoes) {
  Camera c = perspective_camera(Perspective{}, 320, 240);
  c.world_from_camera = world_from_camera_look_at({0.3, 1.2, 4}, {0, 0.5, 0});
  Matrix4 raster_from_world = c.raster_from_ndc() * c.projection_matrix() * c.view_matrix();
  Point3d p(0.2, 0.7, -0.4);
  Vector4d clip = raster_from_world * Vector4d(p.x, p.y, p.z, 1);
  auto projected = c.project(p);
  ASSERT_TRUE(projected);
  EXPECT_NEAR(clip.x / clip.w, projected->film_point.x, 1e-9);
  EXPECT_NEAR(clip.y / clip.w, projected->film_point.y, 1e-9);
  EXPECT_NEAR(clip.w, projected->depth_m, 1e-12);  // OpenGL's w is the eye depth
}

TEST(Camera, NearMapsToMinusOneAndFarToPlusOne) {
  Camera c = perspective_camera(Perspective{}, 64, 64);
  c.near_m = 0.3;
  c.far_m = 12;
  for (auto [depth, ndc_z] : {std::pair{0.3, -1.0}, std::pair{12.0, 1.0}}) {
    Vector4d clip = c.projection_matrix() * Vector4d(0, 0, -depth, 1);
    EXPECT_NEAR(clip.z / clip.w, ndc_z, 1e-12);
  }
}

TEST(Camera, UnprojectInvertsProject) {
  Camera c = perspective_camera(Perspective{}, 320, 200);
  c.world_from_camera = world_from_camera_look_at({1, 1, 1}, {0, 0, -1});
  for (Point3d p : {Point3d(0, 0, -1), Point3d(0.1, -0.05, -0.8), Point3d(-0.3, -0.2, -1.6)}) {
    auto projected = c.project(p);
    ASSERT_TRUE(projected);
    auto back = c.unproject(projected->film_point, projected->depth_m);
    ASSERT_TRUE(back);
    EXPECT_NEAR(back->x, p.x, 1e-12);
    EXPECT_NEAR(back->y, p.y, 1e-12);
    EXPECT_NEAR(back->z, p.z, 1e-12);
  }
  // The inverse matrices take a pixel and its NDC depth back to the same point.
  Point3d p(0.25, 0.1, -0.8);
  Vector4d clip = c.projection_matrix() * c.view_matrix() * Vector4d(p.x, p.y, p.z, 1);
  Vector4d ndc = clip * (1 / clip.w);
  Matrix4 world_from_ndc = *inverse(c.projection_matrix() * c.view_matrix());
  Vector4d back = world_from_ndc * ndc;
  EXPECT_NEAR(back.x / back.w, p.x, 1e-9);
  EXPECT_NEAR(back.y / back.w, p.y, 1e-9);
  EXPECT_NEAR(back.z / back.w, p.z, 1e-9);
}

TEST(Camera, ProjectRejectsPointsItCannotSee) {
  Camera c = perspective_camera(Perspective{}, 100, 100);
  c.near_m = 0.5;
  c.far_m = 10;
  EXPECT_FALSE(c.project({0, 0, 1}));     // behind
  EXPECT_FALSE(c.project({0, 0, -0.4}));  // nearer than near
  EXPECT_FALSE(c.project({0, 0, -11}));   // beyond far
  EXPECT_FALSE(c.project({10, 0, -1}));   // off the film
  EXPECT_TRUE(c.project({0, 0, -5}));
}

TEST(Camera, RaysStartAtTheNearPlaneAndEndAtTheFarPlane) {
  Camera c = perspective_camera(Perspective{}, 100, 100);
  c.near_m = 0.5;
  c.far_m = 10;
  auto ray = c.generate_ray({0, 0});
  ASSERT_TRUE(ray);
  double depth_per_t = -ray->direction.z;
  EXPECT_NEAR(ray->t_min * depth_per_t, 0.5, 1e-12);
  EXPECT_NEAR(ray->t_max * depth_per_t, 10, 1e-12);
}

// The tracer prepares the camera once per render (screen window, lens radius and a fixed
// transform computed once); its rays must be the window_from_raster rays bit for bit, for an
// off-centre window (lens shift) and a non-square film, and the same from a prepared camera
// reused across calls as from generate_ray.
TEST(Camera, PreparedCameraRaysAreWindowFromRasterRaysExactly) {
  Perspective p;
  p.lens_shift = {0.13, -0.07};
  Camera c = perspective_camera(p, 173, 91);
  const PreparedCamera prepared = c.prepare();
  for (double x : {0.0, 0.37, 17.5, 100.25, 173.0})
    for (double y : {0.0, 3.5, 45.125, 91.0}) {
      Point2d w = c.window_from_raster({x, y});
      Vector3d d = normalize(Vector3d(w.x, w.y, -1));
      Vector3d expected = d / length(d);  // the identity transform, then the stretch
      auto ray = prepared.generate_ray({x, y});
      ASSERT_TRUE(ray);
      EXPECT_EQ(ray->direction.x, expected.x) << x << ", " << y;
      EXPECT_EQ(ray->direction.y, expected.y) << x << ", " << y;
      EXPECT_EQ(ray->direction.z, expected.z) << x << ", " << y;
    }
  // Depth of field and a moving camera: reused preparation = per-call preparation.
  c.lens.depth_of_field = true;
  c.lens.f_number = 2;
  c.lens.focus_distance_m = 3;
  c.world_from_camera = AnimatedTransform({{0, Transform()}, {1, Transform::translate({1, 2, 3})}});
  const PreparedCamera moving = c.prepare();
  for (double t : {0.0, 0.25, 1.0})
    for (Point2d lens : {Point2d(0.1, 0.9), Point2d(0.5, 0.5), Point2d(0.77, 0.31)}) {
      auto a = moving.generate_ray({60.5, 20.25}, lens, t),
           b = c.generate_ray({60.5, 20.25}, lens, t);
      ASSERT_TRUE(a && b);
      EXPECT_EQ(a->origin.x, b->origin.x);
      EXPECT_EQ(a->origin.y, b->origin.y);
      EXPECT_EQ(a->origin.z, b->origin.z);
      EXPECT_EQ(a->direction.x, b->direction.x);
      EXPECT_EQ(a->direction.y, b->direction.y);
      EXPECT_EQ(a->direction.z, b->direction.z);
      EXPECT_EQ(a->t_min, b->t_min);
      EXPECT_EQ(a->t_max, b->t_max);
    }
}

}  // namespace
}  // namespace obscura
