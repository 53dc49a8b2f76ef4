// Calibration files round trip: a camera exported to each format and read back projects world
// points to the same pixels (1e-9 px), and the exported K, R, t of a perspective camera project
// world points where Camera::project puts them.
#include <gtest/gtest.h>

#include <random>

#include "obscura/camera/frames.h"
#include "obscura/io/calibration_file.h"
#include "obscura/io/colmap_model.h"
#include "obscura/io/lens_model_coefficients.h"
#include "obscura/math/error.h"

namespace obscura {
namespace {

Camera calibrated_camera(const LensModel& lens, double skew = 0) {
  Camera c;
  c.name = "shot_007.png";
  CalibratedProjection p;
  p.k = {.fx = 612.25, .fy = 598.5, .cx = 331.75, .cy = 228.125, .skew = skew};
  p.width_px = 640;
  p.height_px = 480;
  p.lens = lens;
  c.projection = p;
  c.film.width_px = 640;
  c.film.height_px = 480;
  c.world_from_camera = world_from_camera_look_at({1.5, 0.7, 4.2}, {-0.3, 0.2, 0.1}, {0.1, 1, 0});
  return c;
}

Camera read_back(const Camera& original, CalibrationFormat format) {
  CameraCalibration exported = calibration_of(original);
  CameraCalibration imported;
  if (format == CalibrationFormat::colmap) {
    ColmapModelText text = colmap_model_text(exported);
    imported = parse_colmap_model(text.cameras, "cameras.txt", &text.images, "images.txt", "");
  } else {
    imported = parse_calibration_text(calibration_text(format, exported), "exported", "");
  }
  Camera back;
  apply_calibration(back, imported);
  return back;
}

// 1000 points seen by `original` (its pixels unprojected at random depths) land on the same
// pixels through `other`.
void expect_same_pixels(const Camera& original, const Camera& other, const std::string& what) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> x(0, original.film.width_px),
      y(0, original.film.height_px), depth(0.5, 20);
  int checked = 0;
  double worst = 0;
  for (int i = 0; i < 1000; ++i) {
    Point2d pixel(x(random), y(random));
    std::optional<Point3d> world = original.unproject(pixel, depth(random));
    if (!world) continue;  // outside a fisheye's image
    std::optional<FilmProjection> a = original.project(*world), b = other.project(*world);
    ASSERT_TRUE(a && b) << what << " at pixel " << pixel.x << ", " << pixel.y;
    worst = std::max({worst, std::abs(a->film_point.x - b->film_point.x),
                      std::abs(a->film_point.y - b->film_point.y)});
    ++checked;
  }
  EXPECT_GT(checked, 500) << what;
  EXPECT_LE(worst, 1e-9) << what;
}

struct LensCase {
  const char* name;
  LensModel lens;
};

std::vector<LensCase> lens_cases() {
  return {
      {"pinhole", PinholeDistortion{}},
      {"opencv-5", lens_model_from_coefficients("opencv", {-0.21, 0.043, 0.0012, -0.0007, 0.011})},
      {"opencv-8", lens_model_from_coefficients(
                       "opencv", {-0.21, 0.043, 0.0012, -0.0007, 0.011, 0.02, -0.003, 0.001})},
      {"kannala-brandt", KannalaBrandt{0.031, -0.0042, 0.0011, -0.0002}},
      {"equidistant", ClassicFisheye{FisheyeMapping::equidistant}},
  };
}

TEST(CalibrationRoundTrip, EveryFormatReproducesThePixels) {
  for (CalibrationFormat format : {CalibrationFormat::opencv_yaml, CalibrationFormat::opencv_json,
                                   CalibrationFormat::colmap, CalibrationFormat::nerf})
    for (const LensCase& lens : lens_cases()) {
      // NeRF's OPENCV model lacks OpenCV's rational terms (refused: see below).
      if (format == CalibrationFormat::nerf && std::string(lens.name) == "opencv-8") continue;
      std::string what = std::string(calibration_format_name(format)) + " " + lens.name;
      Camera original = calibrated_camera(lens.lens);
      expect_same_pixels(original, read_back(original, format), what);
    }
}

TEST(CalibrationRoundTrip, OpenCvFilesKeepEveryCoefficientSkewAndFieldLimit) {
  std::vector<double> all = {-0.21, 0.043, 0.0012, -0.0007, 0.011,  0.02, -0.003,
                             0.001, 0.002, -0.001, 0.0015,  0.0004, 0.01, -0.02};
  Camera original = calibrated_camera(lens_model_from_coefficients("opencv", all), 1.25);
  std::get<CalibratedProjection>(original.projection).max_field_angle_degrees = 40;
  for (CalibrationFormat format :
       {CalibrationFormat::opencv_yaml, CalibrationFormat::opencv_json}) {
    Camera back = read_back(original, format);
    const auto& p = std::get<CalibratedProjection>(back.projection);
    EXPECT_EQ(lens_model_coefficients(p.lens), all);
    EXPECT_EQ(p.k.skew, 1.25);
    EXPECT_EQ(p.max_field_angle_degrees, 40);
    expect_same_pixels(original, back, calibration_format_name(format));
  }
  // A fisheye limited to 100° off axis (a 200° lens).
  Camera fisheye = calibrated_camera(KannalaBrandt{0.02, 0.001, 0, 0});
  std::get<CalibratedProjection>(fisheye.projection).k.fx = 150;
  std::get<CalibratedProjection>(fisheye.projection).k.fy = 150;
  std::get<CalibratedProjection>(fisheye.projection).max_field_angle_degrees = 100;
  expect_same_pixels(fisheye, read_back(fisheye, CalibrationFormat::opencv_yaml), "200° fisheye");
}

// A shifted perspective camera with non-square pixels: u = K·[R|t]·X computed by hand from the
// exported numbers lands where Camera::project puts X (raster = u + ½).
TEST(CalibrationRoundTrip, ExportedPerspectiveKAndPoseProjectAsTheCamera) {
  Camera c;
  Perspective p;
  p.focal_length_mm = 42;
  p.sensor_width_mm = 36;
  p.sensor_height_mm = 24;
  p.sensor_fit = SensorFit::horizontal;
  p.lens_shift = {0.07, -0.04};
  c.projection = p;
  c.film.width_px = 720;
  c.film.height_px = 400;
  c.film.pixel_aspect = 1.2;
  c.world_from_camera = world_from_camera_look_at({-2, 1.5, 3}, {0.4, 0.1, -0.5});
  c.validate();
  for (CalibrationFormat format :
       {CalibrationFormat::opencv_yaml, CalibrationFormat::opencv_json, CalibrationFormat::nerf}) {
    CameraCalibration exported =
        parse_calibration_text(calibration_text(format, calibration_of(c)), "exported", "");
    const Intrinsics& k = exported.projection.k;
    EXPECT_NE(k.fx, k.fy) << "non-square pixels";
    CvExtrinsics e = cv_extrinsics(*exported.world_from_camera);
    std::mt19937 random(3);
    std::uniform_real_distribution<double> coordinate(-2, 2);
    int seen = 0;
    for (int i = 0; i < 1000; ++i) {
      Point3d world(coordinate(random), coordinate(random), coordinate(random));
      std::optional<FilmProjection> projected = c.project(world);
      if (!projected) continue;
      double x[3];
      for (int row = 0; row < 3; ++row)
        x[row] = e.r[row][0] * world.x + e.r[row][1] * world.y + e.r[row][2] * world.z + e.t[row];
      double u = k.fx * x[0] / x[2] + k.skew * x[1] / x[2] + k.cx, v = k.fy * x[1] / x[2] + k.cy;
      EXPECT_NEAR(u + 0.5, projected->film_point.x, 1e-8);
      EXPECT_NEAR(v + 0.5, projected->film_point.y, 1e-8);
      ++seen;
    }
    EXPECT_GT(seen, 100);
  }
}

TEST(CalibrationRoundTrip, FormatsRefuseWhatTheyCannotExpress) {
  Camera ortho;
  ortho.projection = Orthographic{};
  EXPECT_THROW(calibration_of(ortho), Error);
  Camera spherical;
  spherical.projection = Equirectangular{};
  EXPECT_THROW(calibration_of(spherical), Error);
  CameraCalibration ftheta = calibration_of(calibrated_camera(FThetaPolynomial{}));
  for (CalibrationFormat f :
       {CalibrationFormat::opencv_yaml, CalibrationFormat::opencv_json, CalibrationFormat::nerf})
    EXPECT_THROW(calibration_text(f, ftheta), Error) << calibration_format_name(f);
  EXPECT_THROW(colmap_model_text(ftheta), Error);
  CameraCalibration skewed = calibration_of(calibrated_camera(PinholeDistortion{}, 2.0));
  EXPECT_THROW(colmap_model_text(skewed), Error);
  EXPECT_THROW(calibration_text(CalibrationFormat::nerf, skewed), Error);
  CameraCalibration rational = calibration_of(calibrated_camera(
      lens_model_from_coefficients("opencv", {0.1, 0.01, 0, 0, 0.001, 0.05, 0, 0})));
  EXPECT_THROW(calibration_text(CalibrationFormat::nerf, rational), Error);
  EXPECT_NO_THROW(colmap_model_text(rational));  // FULL_OPENCV has k4..k6
}

}  // namespace
}  // namespace obscura
