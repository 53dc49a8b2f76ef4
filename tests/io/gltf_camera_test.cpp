// glTF cameras: the projection matrices the glTF 2.0 specification writes out (Appendix:
// projection matrices), and Blender's equivalent settings.
#include "obscura/io/gltf_camera.h"

#include <cmath>
#include <cstring>

#include <gtest/gtest.h>

#include "obscura/math/error.h"

namespace obscura {
namespace {

// glTF 2.0, "Projection Matrices": finite perspective
//   [1/(a·tan(y/2)), 0, 0, 0; 0, 1/tan(y/2), 0, 0; 0, 0, (f+n)/(n−f), 2fn/(n−f); 0, 0, −1, 0],
// infinite: the third row becomes [0, 0, −1, −2n]; orthographic
//   [1/xmag, 0, 0, 0; 0, 1/ymag, 0, 0; 0, 0, 2/(n−f), (f+n)/(n−f); 0, 0, 0, 1].
TEST(GltfCamera, PerspectiveMatrixIsTheSpecs) {
  double y = 0.7, a = 1.6, n = 0.05, f = 200;
  Camera c =
      from_gltf_perspective({.yfov_radians = y, .aspect_ratio = a, .znear_m = n, .zfar_m = f}, 800);
  EXPECT_EQ(c.film.width_px, 800);
  EXPECT_EQ(c.film.height_px, 500);
  Matrix4 m = c.projection_matrix();
  EXPECT_NEAR(m[0][0], 1 / (a * std::tan(y / 2)), 1e-12);
  EXPECT_NEAR(m[1][1], 1 / std::tan(y / 2), 1e-12);
  EXPECT_NEAR(m[2][2], (f + n) / (n - f), 1e-12);
  EXPECT_NEAR(m[2][3], 2 * f * n / (n - f), 1e-12);
  EXPECT_EQ(m[3][2], -1);
  Camera infinite = from_gltf_perspective(
      {.yfov_radians = y, .aspect_ratio = a, .znear_m = n, .zfar_m = std::nullopt});
  EXPECT_EQ(infinite.projection_matrix()[2][2], -1);
  EXPECT_NEAR(infinite.projection_matrix()[2][3], -2 * n, 1e-15);
  // And back: the vertical angle and the aspect ratio survive.
  GltfCamera g = to_gltf(c);
  ASSERT_TRUE(g.perspective);
  EXPECT_NEAR(g.perspective->yfov_radians, y, 1e-12);
  EXPECT_NEAR(*g.perspective->aspect_ratio, a, 1e-12);
}

TEST(GltfCamera, OrthographicMatrixIsTheSpecs) {
  Camera c =
      from_gltf_orthographic({.xmag_m = 3, .ymag_m = 1.5, .znear_m = 0.1, .zfar_m = 50}, 600);
  EXPECT_EQ(c.film.height_px, 300);
  Matrix4 m = c.projection_matrix();
  EXPECT_NEAR(m[0][0], 1 / 3.0, 1e-12);
  EXPECT_NEAR(m[1][1], 1 / 1.5, 1e-12);
  EXPECT_NEAR(m[2][2], 2 / (0.1 - 50), 1e-12);
  EXPECT_NEAR(m[2][3], (50 + 0.1) / (0.1 - 50), 1e-12);
  GltfCamera g = to_gltf(c);
  ASSERT_TRUE(g.orthographic);
  EXPECT_NEAR(g.orthographic->xmag_m, 3, 1e-12);
}

TEST(GltfCamera, RejectsOutOfRangeValuesNamingTheProperty) {
  try {
    from_gltf_perspective({.yfov_radians = 3.2,
                           .aspect_ratio = std::nullopt,
                           .znear_m = 0.1,
                           .zfar_m = std::nullopt});
    ADD_FAILURE();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("yfov"), std::string::npos);
  }
  EXPECT_THROW(
      from_gltf_perspective(
          {.yfov_radians = 1, .aspect_ratio = std::nullopt, .znear_m = 0, .zfar_m = std::nullopt}),
      Error);
  EXPECT_THROW(from_gltf_orthographic({.xmag_m = 0, .ymag_m = 1, .znear_m = 0, .zfar_m = 1}),
               Error);
}

TEST(GltfCamera, BlenderEquivalent) {
  Camera c;
  Perspective p;
  p.focal_length_mm = 85;
  p.sensor_fit = SensorFit::vertical;
  c.projection = p;
  c.lens.depth_of_field = true;
  c.lens.f_number = 1.8;
  c.lens.focus_distance_m = 3;
  BlenderCamera b = to_blender(c);
  EXPECT_STREQ(b.type, "PERSP");
  EXPECT_EQ(b.lens_mm, 85);
  EXPECT_STREQ(b.sensor_fit, "VERTICAL");
  EXPECT_TRUE(b.use_dof);
  EXPECT_NEAR(b.fstop, 1.8, 1e-12);
}

}  // namespace
}  // namespace obscura
