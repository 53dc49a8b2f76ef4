// The calibrated camera against OpenCV, the toolbox whose conventions it follows: every point a
// calibrated Camera projects lands where cv::projectPoints / cv::fisheye::projectPoints put it,
// and every pixel it unprojects is the ray cv::undistortPoints finds.
#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/calib3d.hpp>
#include <random>
#include <vector>

#include "obscura/camera/calibrated_projection.h"
#include "obscura/camera/camera.h"
#include "white_on_black.h"

namespace obscura {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kPoints = 10000;

// OpenCV's camera frame (X right, Y down, Z forward) to Obscura's (Y up, looking down −Z).
Point3d obscura_point(const cv::Point3d& p) {
  return {p.x, -p.y, -p.z};
}

cv::Mat camera_matrix(const Intrinsics& k) {
  return (cv::Mat_<double>(3, 3) << k.fx, k.skew, k.cx, 0, k.fy, k.cy, 0, 0, 1);
}

// Random points in front of the camera whose field angle stays inside `max_angle` (radians).
std::vector<cv::Point3d> random_points(double max_angle, uint32_t seed, bool behind_ok = false) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0, 1);
  std::vector<cv::Point3d> points;
  for (int i = 0; i < kPoints; ++i) {
    // Uniform in solid angle inside the cone, at distances from 0.5 to 20 m.
    double cos_max = std::cos(max_angle);
    double z = 1 - unit(rng) * (1 - cos_max), phi = 2 * kPi * unit(rng);
    double s = std::sqrt(std::max(0.0, 1 - z * z)), distance = 0.5 + 19.5 * unit(rng);
    if (!behind_ok && z <= 1e-3) z = 1e-3;
    points.push_back({distance * s * std::cos(phi), distance * s * std::sin(phi), distance * z});
  }
  return points;
}

// Projects `points` with Obscura's camera and with OpenCV's projection and returns the largest
// difference in pixels; every point must land on the film.
double worst_projection_difference(const Camera& camera, const std::vector<cv::Point3d>& points,
                                   const std::vector<cv::Point2d>& opencv_pixels) {
  double worst = 0;
  int projected = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    auto p = camera.project(obscura_point(points[i]));
    if (!p) continue;
    ++projected;
    // Obscura's raster puts pixel centres at half-integers, OpenCV's at integers.
    worst = std::max(worst, std::hypot(p->film_point.x - 0.5 - opencv_pixels[i].x,
                                       p->film_point.y - 0.5 - opencv_pixels[i].y));
  }
  EXPECT_EQ(projected, int(points.size())) << "every point must land on the film";
  return worst;
}

std::vector<double> opencv_coefficients(const PinholeDistortion& d) {
  return {d.k1, d.k2, d.p1, d.p2, d.k3, d.k4, d.k5, d.k6, d.s1, d.s2, d.s3, d.s4, d.tau_x, d.tau_y};
}

struct PinholeCase {
  const char* name;
  PinholeDistortion distortion;
};

const PinholeCase kPinholeCases[] = {
    {"ideal", {}},
    {"five coefficients", {.k1 = -0.27, .k2 = 0.08, .p1 = 0.0011, .p2 = -0.0007, .k3 = -0.01}},
    {"rational, prism and tilt",
     {.k1 = -0.21,
      .k2 = 0.05,
      .p1 = 0.0012,
      .p2 = -0.0009,
      .k3 = -0.004,
      .k4 = 0.03,
      .k5 = 0.004,
      .k6 = 0.0007,
      .s1 = 0.0011,
      .s2 = -0.0004,
      .s3 = 0.0007,
      .s4 = -0.0002,
      .tau_x = 0.012,
      .tau_y = -0.017}},
    {"strong pincushion k1 = 0.5", {.k1 = 0.5}},
};

TEST(CalibratedCameraVsOpenCV, PinholeProjectsAsProjectPoints) {
  Intrinsics k{.fx = 905.5, .fy = 887.25, .cx = 3911.7, .cy = 3388.2};
  for (const PinholeCase& c : kPinholeCases) {
    SCOPED_TRACE(c.name);
    Camera camera = test::calibrated_camera({.k = k, .lens = c.distortion}, 7840, 6800);
    LensMap map(c.distortion);
    // Inside the validity region, on a film wide enough to show all of it.
    double max_angle = std::min(map.max_field_angle() * 0.95, 55 * kPi / 180);
    std::vector<cv::Point3d> points = random_points(max_angle, 7);
    std::vector<cv::Point2d> pixels;
    cv::projectPoints(points, cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0), camera_matrix(k),
                      opencv_coefficients(c.distortion), pixels);
    EXPECT_LE(worst_projection_difference(camera, points, pixels), 1e-4);
  }
}

TEST(CalibratedCameraVsOpenCV, FisheyeProjectsAsFisheyeProjectPointsWithSkew) {
  // cv::fisheye's skew is α with u = fx·(x' + α·y') + cx: K's skew entry is fx·α.
  double alpha = 0.0021;
  KannalaBrandt d{.k1 = 0.031, .k2 = -0.012, .k3 = 0.0041, .k4 = -0.0009};
  Intrinsics k{.fx = 610.3, .fy = 608.9, .cx = 2022.4, .cy = 1971.9, .skew = 610.3 * alpha};
  Camera camera = test::calibrated_camera({.k = k, .lens = d}, 4048, 3936);
  // cv::fisheye divides by Z: compare over the forward hemisphere (up to 85°).
  std::vector<cv::Point3d> points = random_points(85 * kPi / 180, 11);
  std::vector<cv::Point2d> pixels;
  cv::Mat K = (cv::Mat_<double>(3, 3) << k.fx, 0, k.cx, 0, k.fy, k.cy, 0, 0, 1);
  cv::fisheye::projectPoints(points, pixels, cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0), K,
                             cv::Vec4d(d.k1, d.k2, d.k3, d.k4), alpha);
  EXPECT_LE(worst_projection_difference(camera, points, pixels), 1e-4);
}

// Random pixels of the image whose rays lie inside the validity region.
std::vector<cv::Point2d> random_pixels(const Camera& camera, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> x(0, camera.film.width_px), y(0, camera.film.height_px);
  std::vector<cv::Point2d> pixels;
  while (pixels.size() < kPoints) {
    Point2d p(x(rng), y(rng));
    if (camera.generate_ray(p)) pixels.push_back({p.x - 0.5, p.y - 0.5});
  }
  return pixels;
}

TEST(CalibratedCameraVsOpenCV, PinholeUnprojectsAsUndistortPointsAndRoundTrips) {
  Intrinsics k{.fx = 905.5, .fy = 887.25, .cx = 641.7, .cy = 362.2};
  cv::TermCriteria exact(cv::TermCriteria::COUNT + cv::TermCriteria::EPS, 200, 1e-15);
  for (const PinholeCase& c : kPinholeCases) {
    SCOPED_TRACE(c.name);
    Camera camera = test::calibrated_camera({.k = k, .lens = c.distortion}, 1280, 720);
    std::vector<cv::Point2d> pixels = random_pixels(camera, 3), undistorted;
    cv::undistortPoints(pixels, undistorted, camera_matrix(k), opencv_coefficients(c.distortion),
                        cv::noArray(), cv::noArray(), exact);
    double worst_vs_opencv = 0, worst_round_trip = 0;
    for (size_t i = 0; i < pixels.size(); ++i) {
      Point2d raster(pixels[i].x + 0.5, pixels[i].y + 0.5);
      auto ray = camera.generate_ray(raster);
      ASSERT_TRUE(ray);
      // The ray's direction in OpenCV's frame, on the plane Z = 1, compared in pixels.
      Vector3d d = ray->direction;
      double x = d.x / -d.z, y = -d.y / -d.z;
      worst_vs_opencv = std::max(worst_vs_opencv, std::hypot((x - undistorted[i].x) * k.fx,
                                                             (y - undistorted[i].y) * k.fy));
      auto back = camera.project(Point3d(0, 0, 0) + d * 3.0);
      ASSERT_TRUE(back);
      worst_round_trip = std::max(worst_round_trip, std::hypot(back->film_point.x - raster.x,
                                                               back->film_point.y - raster.y));
    }
    EXPECT_LE(worst_vs_opencv, 1e-4);
    EXPECT_LE(worst_round_trip, 1e-6);
  }
}

TEST(CalibratedCameraVsOpenCV, FisheyeUnprojectsAsFisheyeUndistortPoints) {
  KannalaBrandt d{.k1 = 0.031, .k2 = -0.012, .k3 = 0.0041, .k4 = -0.0009};
  Intrinsics k{.fx = 410.3, .fy = 408.9, .cx = 640.4, .cy = 481.9};
  Camera camera =
      test::calibrated_camera({.k = k, .lens = d, .max_field_angle_degrees = 80}, 1280, 960);
  std::vector<cv::Point2d> pixels = random_pixels(camera, 5), undistorted;
  cv::Mat K = camera_matrix(k);
  cv::fisheye::undistortPoints(
      pixels, undistorted, K, cv::Vec4d(d.k1, d.k2, d.k3, d.k4), cv::noArray(), cv::noArray(),
      cv::TermCriteria(cv::TermCriteria::COUNT + cv::TermCriteria::EPS, 200, 1e-15));
  double worst = 0;
  for (size_t i = 0; i < pixels.size(); ++i) {
    auto ray = camera.generate_ray({pixels[i].x + 0.5, pixels[i].y + 0.5});
    ASSERT_TRUE(ray);
    Vector3d v = ray->direction;
    double x = v.x / -v.z, y = -v.y / -v.z;
    // Compared as angles (tan θ grows fast near 80°), in pixels of the image circle.
    double angle_ours = std::atan(std::hypot(x, y));
    double angle_cv = std::atan(std::hypot(undistorted[i].x, undistorted[i].y));
    worst = std::max(worst, std::abs(angle_ours - angle_cv) * k.fx);
  }
  EXPECT_LE(worst, 1e-4);
}

}  // namespace
}  // namespace obscura
