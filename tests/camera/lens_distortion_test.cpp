// The calibrated lens models against the optics of their textbook definitions: the classic
// fisheye mappings' image radii, the fold-over point of strong barrel distortion, a 200° fisheye
// that sees behind itself, and K's scaling with the image (OpenCV's own comparisons are in
// lens_distortion_opencv_test.cpp).
#include "obscura/camera/lens_distortion.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "obscura/camera/calibrated_projection.h"
#include "obscura/camera/camera.h"
#include "obscura/camera/intrinsics.h"
#include "obscura/math/error.h"
#include "white_on_black.h"

namespace obscura {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A world point at field angle θ from the optical axis (Obscura's −Z), towards +X (right).
Point3d at_field_angle(double theta, double distance = 2) {
  return {distance * std::sin(theta), 0, -distance * std::cos(theta)};
}

TEST(LensModels, ClassicFisheyesPlaceRaysAtTheirTextbookRadii) {
  // r = f·θ, 2f·sin(θ/2), 2f·tan(θ/2), f·sin θ, measured from the principal point.
  struct Case {
    FisheyeMapping mapping;
    double (*radius)(double);
  } cases[] = {
      {FisheyeMapping::equidistant, [](double t) { return t; }},
      {FisheyeMapping::equisolid, [](double t) { return 2 * std::sin(t / 2); }},
      {FisheyeMapping::stereographic, [](double t) { return 2 * std::tan(t / 2); }},
      {FisheyeMapping::orthographic, [](double t) { return std::sin(t); }},
  };
  Intrinsics k{.fx = 250, .fy = 250, .cx = 511.5, .cy = 511.5};
  for (const Case& c : cases) {
    Camera camera =
        test::calibrated_camera({.k = k, .lens = ClassicFisheye{c.mapping}}, 1024, 1024);
    for (double degrees : {10.0, 35.0, 60.0, 85.0}) {
      double theta = degrees * kPi / 180;
      auto p = camera.project(at_field_angle(theta));
      ASSERT_TRUE(p) << degrees;
      EXPECT_NEAR(p->film_point.x - 512, 250 * c.radius(theta), 1e-9) << degrees;
      EXPECT_NEAR(p->film_point.y, 512, 1e-9);
      EXPECT_NEAR(p->depth_m, 2, 1e-12) << "fisheyes measure depth as distance";
    }
  }
}

TEST(LensModels, StrongBarrelDistortionStopsWhereItFoldsOver) {
  // r·(1 + k1 r²) stops growing at r = 1/√(−3 k1).
  LensMap map(PinholeDistortion{.k1 = -0.5});
  EXPECT_NEAR(map.max_field_angle(), std::atan(1 / std::sqrt(1.5)), 1e-9);
  // A ray just inside is seen; just outside is not, and no pixel maps beyond the fold.
  double edge = map.max_field_angle();
  EXPECT_TRUE(map.forward({std::tan(edge - 1e-4), 0, 1}));
  EXPECT_FALSE(map.forward({std::tan(edge + 1e-4), 0, 1}));
  EXPECT_FALSE(map.inverse({map.max_image_radius() * 1.001, 0}));
}

TEST(LensModels, TwoHundredDegreeFisheyeSeesBehindItselfAndInvertsEverywhere) {
  KannalaBrandt d{.k1 = -0.04, .k2 = 0.003};
  Intrinsics k{.fx = 180, .fy = 180, .cx = 399.5, .cy = 399.5};
  Camera camera =
      test::calibrated_camera({.k = k, .lens = d, .max_field_angle_degrees = 100}, 800, 800);
  // 95° from the axis: behind the lens plane, still on the film.
  auto p = camera.project(at_field_angle(95 * kPi / 180));
  ASSERT_TRUE(p);
  auto ray = camera.generate_ray(p->film_point);
  ASSERT_TRUE(ray);
  EXPECT_NEAR(std::acos(-ray->direction.z) * 180 / kPi, 95, 1e-9);
  EXPECT_FALSE(camera.project(at_field_angle(101 * kPi / 180)));
  // Every pixel either sees a ray that projects back onto it or nothing: never a stall, never
  // a wrong ray.
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(0, 800);
  int seen = 0;
  for (int i = 0; i < 20000; ++i) {
    Point2d film(u(rng), u(rng));
    auto r = camera.generate_ray(film);
    if (!r) continue;
    ++seen;
    auto back = camera.project(r->origin + r->direction * 5.0);
    ASSERT_TRUE(back);
    ASSERT_NEAR(back->film_point.x, film.x, 1e-6);
    ASSERT_NEAR(back->film_point.y, film.y, 1e-6);
  }
  // The image circle (radius 180·r(100°) ≈ 285 px) covers about 40 % of the 800² image.
  EXPECT_GT(seen, 7000);
}

TEST(LensModels, KannalaBrandtIsTheOddFThetaPolynomial) {
  KannalaBrandt kb{.k1 = 0.02, .k2 = -0.01, .k3 = 0.003, .k4 = -0.0005};
  FThetaPolynomial ft{.c = {1, 0, kb.k1, 0, kb.k2, 0}};
  // The polynomial's sixth power cannot hold k3 θ⁷ and k4 θ⁹: compare where they are negligible.
  LensMap a(KannalaBrandt{.k1 = kb.k1, .k2 = kb.k2}), b(ft);
  for (double theta = 0.05; theta < 1.5; theta += 0.1) {
    Vector3d ray(std::sin(theta), 0, std::cos(theta));
    EXPECT_NEAR(a.forward(ray)->x, b.forward(ray)->x, 1e-12);
  }
}

TEST(LensModels, KScalesWithTheImage) {
  Intrinsics k{.fx = 1000, .fy = 990, .cx = 639.5, .cy = 361.0, .skew = 2};
  Camera camera = test::calibrated_camera({.k = k, .width_px = 1280, .height_px = 720}, 640, 360);
  Intrinsics half = intrinsics(camera);
  EXPECT_DOUBLE_EQ(half.fx, 500);
  EXPECT_DOUBLE_EQ(half.fy, 495);
  EXPECT_DOUBLE_EQ(half.cx, 319.5);  // the image centre stays the centre
  EXPECT_DOUBLE_EQ(half.cy, 180.25);
  EXPECT_DOUBLE_EQ(half.skew, 1);
  // A point on the optical axis lands on the principal point in either size.
  auto p = camera.project({0, 0, -3});
  ASSERT_TRUE(p);
  EXPECT_NEAR(p->film_point.x, 320, 1e-12);
  EXPECT_NEAR(p->film_point.y, 180.75, 1e-12);
}

TEST(LensModels, PinholeDepthIsAlongTheAxisAndUnprojectInvertsProject) {
  Camera camera = test::calibrated_camera(
      {.k = {.fx = 500, .fy = 520, .cx = 300, .cy = 200}, .lens = PinholeDistortion{.k1 = -0.2}},
      640, 480);
  Point3d world(0.4, -0.3, -2.5);
  auto p = camera.project(world);
  ASSERT_TRUE(p);
  EXPECT_DOUBLE_EQ(p->depth_m, 2.5);
  auto back = camera.unproject(p->film_point, p->depth_m);
  ASSERT_TRUE(back);
  EXPECT_NEAR(back->x, world.x, 1e-12);
  EXPECT_NEAR(back->y, world.y, 1e-12);
  EXPECT_NEAR(back->z, world.z, 1e-12);
}

TEST(LensModels, InvalidParametersAreRejectedByName) {
  auto message = [](const CalibratedProjection& p) {
    try {
      validate(p);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  Intrinsics k{.fx = 500, .fy = 500, .cx = 320, .cy = 240};
  EXPECT_NE(message({.k = {.fx = 0, .fy = 500}}).find("fx"), std::string::npos);
  EXPECT_NE(message({.k = k, .lens = PinholeDistortion{.k2 = NAN}}).find("k2"), std::string::npos);
  EXPECT_NE(message({.k = k, .lens = FThetaPolynomial{.c = {-1, 0, 0, 0, 0, 0}}}).find("ftheta"),
            std::string::npos);
  EXPECT_NE(message({.k = k, .max_field_angle_degrees = 200}).find("max_field_angle"),
            std::string::npos);
  EXPECT_NE(message({.k = k, .width_px = 640}).find("image_size"), std::string::npos);
}

}  // namespace
}  // namespace obscura
