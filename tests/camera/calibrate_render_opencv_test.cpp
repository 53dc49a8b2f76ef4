// Calibrate what we render: a checkerboard seen by a distorted, non-square-pixel calibrated camera
// from 20 poses; OpenCV detects the corners and cv::calibrateCamera must recover the camera we
// rendered with. The calibration images are the rasterizer's (drawn through lens views, fast);
// the second test holds them to the tracer's: the corners land in the same places.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "obscura/camera/calibrated_projection.h"
#include "obscura/camera/frames.h"
#include "obscura/raster/lens_warp.h"
#include "obscura/raster/scene_rasterizer.h"
#include "obscura/scene/scene.h"
#include "obscura/trace/render.h"
#include "white_on_black.h"

namespace obscura {
namespace {

constexpr int kSquaresX = 11,
              kSquaresY = 8;      // inner corners 10 × 7: not symmetric under a half turn
constexpr double kSquare = 0.08;  // metres
const cv::Size kInnerCorners(kSquaresX - 1, kSquaresY - 1);

// White emitting squares on black, with a white border one square wide (the quiet zone OpenCV's
// detector looks for), in the plane z = 0 centred on the origin.
Scene checkerboard() {
  Scene scene = test::white_on_black("checkerboard");
  Mesh mesh;
  mesh.name = "board";
  const double x0 = -0.5 * (kSquaresX + 2) * kSquare, y0 = -0.5 * (kSquaresY + 2) * kSquare;
  for (int j = 0; j < kSquaresY + 2; ++j)
    for (int i = 0; i < kSquaresX + 2; ++i) {
      bool border = i == 0 || j == 0 || i == kSquaresX + 1 || j == kSquaresY + 1;
      if (!border && (i + j) % 2 == 0) continue;
      auto base = uint32_t(mesh.positions.size());
      double x = x0 + i * kSquare, y = y0 + j * kSquare;
      for (auto [dx, dy] : {std::pair{0, 0}, std::pair{1, 0}, std::pair{1, 1}, std::pair{0, 1}})
        mesh.positions.push_back(Point3f(float(x + dx * kSquare), float(y + dy * kSquare), 0));
      for (uint32_t k : {0u, 1u, 2u, 0u, 2u, 3u}) mesh.indices.push_back(base + k);
    }
  scene.add_mesh(mesh);
  return scene;
}

// The board's inner corners in its own plane (OpenCV's object points, z = 0).
std::vector<cv::Point3f> inner_corners() {
  std::vector<cv::Point3f> points;
  const double x0 = -0.5 * (kSquaresX + 2) * kSquare, y0 = -0.5 * (kSquaresY + 2) * kSquare;
  for (int j = 2; j <= kSquaresY; ++j)
    for (int i = 2; i <= kSquaresX; ++i)
      points.push_back(cv::Point3f(float(x0 + i * kSquare), float(y0 + j * kSquare), 0));
  return points;
}

const CalibratedProjection kCamera{
    .k = {.fx = 1220, .fy = 1232.2, .cx = 647.4, .cy = 473.7},
    .lens = PinholeDistortion{.k1 = -0.28, .k2 = 0.12, .p1 = 0.006, .p2 = -0.004}};

Camera camera_at(Point3d eye, Point3d target, Vector3d up = {0, 1, 0}, int width = 1280) {
  Camera c;
  // K is the 1280 x 960 calibration's; smaller films scale it.
  c.projection = CalibratedProjection{kCamera.k, 1280, 960, kCamera.lens, 0};
  c.film.width_px = width;
  c.film.height_px = width * 3 / 4;
  c.near_m = 0.01;
  c.world_from_camera = world_from_camera_look_at(eye, target, up);
  c.validate();
  return c;
}

cv::Mat gray_float(const Image& image) {
  cv::Mat m(image.height, image.width, CV_32F);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) m.at<float>(y, x) = image.at(x, y, 1);
  return m;
}

cv::Mat gray(const Image& image) {
  cv::Mat m(image.height, image.width, CV_8U);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      m.at<uint8_t>(y, x) = uint8_t(std::lround(std::clamp(image.at(x, y, 1), 0.f, 1.f) * 255));
  return m;
}

Image trace_board(const Scene& scene, const Camera& camera) {
  TraceScene trace(scene, std::make_shared<EmbreeDevice>());
  Film film(camera.film.width_px, camera.film.height_px);
  render(trace, camera, test::FirstHitWhite(), {.samples_per_pixel = 32, .seed = 1}, film);
  return film.to_image();
}

Image raster_board(const Scene& scene, const Camera& camera, int msaa = 4) {
  raster::RasterSettings settings;
  settings.msaa_samples = msaa;
  settings.surface_lights = false;
  raster::SceneRasterizer rasterizer(scene, settings);
  Film film(camera.film.width_px, camera.film.height_px);
  raster::render_through_lens(rasterizer, camera, {}, film);
  return film.to_image();
}

// The inner corners OpenCV finds, to a tenth of a pixel or better, in the order of
// inner_corners() (matched to where the camera projects them, which only pairs them up).
std::vector<cv::Point2f> detect_corners(const Image& image, const Camera& camera,
                                        const Transform& world_from_board) {
  cv::Mat g = gray(image);
  std::vector<cv::Point2f> found;
  if (!cv::findChessboardCorners(g, kInnerCorners, found, cv::CALIB_CB_ADAPTIVE_THRESH)) return {};
  cv::cornerSubPix(gray_float(image), found, cv::Size(7, 7), cv::Size(-1, -1),
                   cv::TermCriteria(cv::TermCriteria::EPS + cv::TermCriteria::COUNT, 100, 1e-5));
  std::vector<cv::Point2f> ordered;
  for (const cv::Point3f& p : inner_corners()) {
    auto at = camera.project(world_from_board(Point3d(p.x, p.y, p.z)));
    if (!at) return {};
    cv::Point2f expected(float(at->film_point.x - 0.5), float(at->film_point.y - 0.5));
    auto nearest = std::min_element(found.begin(), found.end(), [&](auto& a, auto& b) {
      return cv::norm(a - expected) < cv::norm(b - expected);
    });
    if (cv::norm(*nearest - expected) > 3) return {};
    ordered.push_back(*nearest);
  }
  return ordered;
}

// 20 views of the board, tilted up to about 45°, rolled up to 20° and spread over the image.
std::vector<Camera> poses(int width = 1280) {
  std::vector<Camera> cameras;
  for (int k = 0; k < 20; ++k) {
    double azimuth = (k % 5 - 2) * 0.35, elevation = (k / 5 - 1.5) * 0.3;
    double distance = 1.3 + 0.12 * (k % 3), roll = ((k * 5) % 7 - 3) * 0.11;
    Point3d eye(distance * std::sin(azimuth) * std::cos(elevation), distance * std::sin(elevation),
                distance * std::cos(azimuth) * std::cos(elevation));
    Point3d target(0.06 * ((k * 7) % 5 - 2), 0.05 * ((k * 3) % 5 - 2), 0);
    Vector3d up(std::sin(roll), std::cos(roll), 0);
    cameras.push_back(camera_at(eye, target, up, width));
  }
  return cameras;
}

TEST(CalibrateWhatWeRender, CalibrateCameraRecoversTheDistortedCamera) {
  Scene scene = checkerboard();
  std::vector<std::vector<cv::Point3f>> object_points;
  std::vector<std::vector<cv::Point2f>> image_points;
  for (const Camera& camera : poses()) {
    std::vector<cv::Point2f> corners = detect_corners(raster_board(scene, camera), camera, {});
    ASSERT_EQ(corners.size(), inner_corners().size()) << "the board must be found in every view";
    object_points.push_back(inner_corners());
    image_points.push_back(corners);
  }
  cv::Mat K, D;
  std::vector<cv::Mat> rvecs, tvecs;
  double rms = cv::calibrateCamera(object_points, image_points, cv::Size(1280, 960), K, D, rvecs,
                                   tvecs, cv::CALIB_FIX_K3);
  const Intrinsics& k = kCamera.k;
  const auto& d = std::get<PinholeDistortion>(kCamera.lens);
  EXPECT_LE(rms, 0.1);
  EXPECT_NEAR(K.at<double>(0, 0), k.fx, 1e-3 * k.fx);
  EXPECT_NEAR(K.at<double>(1, 1), k.fy, 1e-3 * k.fy);
  EXPECT_NEAR(K.at<double>(0, 2), k.cx, 1e-3 * k.cx);
  EXPECT_NEAR(K.at<double>(1, 2), k.cy, 1e-3 * k.cy);
  EXPECT_NEAR(D.at<double>(0), d.k1, 0.01 * std::abs(d.k1));
  EXPECT_NEAR(D.at<double>(1), d.k2, 0.01 * std::abs(d.k2));
  EXPECT_NEAR(D.at<double>(2), d.p1, 0.01 * std::abs(d.p1));
  EXPECT_NEAR(D.at<double>(3), d.p2, 0.01 * std::abs(d.p2));
  std::printf(
      "calibrateCamera: rms %.4f px, fx %.3f fy %.3f cx %.3f cy %.3f, k1 %.5f k2 %.5f "
      "p1 %.6f p2 %.6f\n",
      rms, K.at<double>(0, 0), K.at<double>(1, 1), K.at<double>(0, 2), K.at<double>(1, 2),
      D.at<double>(0), D.at<double>(1), D.at<double>(2), D.at<double>(3));
}

TEST(CalibrateWhatWeRender, RasterizerAndTracerPutTheCornersInTheSamePlaces) {
  Scene scene = checkerboard();
  std::vector<Camera> cameras = poses(640);
  double worst = 0;
  for (int k : {0, 9, 18}) {
    const Camera& camera = cameras[size_t(k)];
    std::vector<cv::Point2f> traced = detect_corners(trace_board(scene, camera), camera, {});
    std::vector<cv::Point2f> drawn = detect_corners(raster_board(scene, camera, 8), camera, {});
    ASSERT_EQ(traced.size(), inner_corners().size());
    ASSERT_EQ(drawn.size(), inner_corners().size());
    cv::Point2f mean;
    for (size_t i = 0; i < traced.size(); ++i) {
      worst = std::max(worst, double(cv::norm(traced[i] - drawn[i])));
      mean += (drawn[i] - traced[i]) / float(traced.size());
    }
    std::printf("pose %d: mean corner offset rasterizer - tracer (%.4f, %.4f) px\n", k, mean.x,
                mean.y);
  }
  std::printf("worst corner difference, rasterizer vs tracer: %.4f px\n", worst);
  EXPECT_LE(worst, 0.1);
}

}  // namespace
}  // namespace obscura
