// COLMAP's text model, written by hand from its documentation (colmap.github.io/format.html and
// cameras.html): pixel coordinates with the top-left pixel's centre at (0.5, 0.5) — Obscura's
// raster coordinates — and poses taking world points into OpenCV's camera frame.
#include "obscura/io/colmap_model.h"

#include <gtest/gtest.h>

#include <cmath>

#include "obscura/math/error.h"

namespace obscura {
namespace {

const std::string kCameras =
    "# Camera list with one line of data per camera:\n"
    "#   CAMERA_ID, MODEL, WIDTH, HEIGHT, PARAMS[]\n"
    "1 PINHOLE 640 480 500 520 320 240\n"
    "2 SIMPLE_RADIAL 800 600 700 400 300 -0.1\n"
    "\n"
    "3 OPENCV_FISHEYE 640 480 300 300 320 240 0.01 0 0 0\n";
const std::string kImages =
    "# Image list with two lines of data per image:\n"
    "1 1 0 0 0 0 0 5 1 front.jpg\n"
    "100.5 200.25 -1 30 40 7\n"
    "2 0.70710678118654757 0 0.70710678118654757 0 0 0 0 2 side.jpg\n"
    "\n";

Camera camera_of(const std::string& image) {
  CameraCalibration c = parse_colmap_model(kCameras, "cameras.txt", &kImages, "images.txt", image);
  Camera camera;
  apply_calibration(camera, c);
  return camera;
}

TEST(ColmapModel, PinholeImageProjectsAsTheFormatSays) {
  Camera c = camera_of("");  // the first image
  const auto& p = std::get<CalibratedProjection>(c.projection);
  EXPECT_EQ(p.k.cx, 319.5);  // COLMAP's 320 is OpenCV's 319.5
  EXPECT_EQ(c.film.width_px, 640);
  // x_cam = (0.1, −0.2, 5): u = 500·0.02 + 320 = 330, v = 520·(−0.04) + 240 = 219.2 in COLMAP's
  // pixels, which are Obscura's raster coordinates.
  std::optional<FilmProjection> f = c.project({0.1, -0.2, 0});
  ASSERT_TRUE(f);
  EXPECT_NEAR(f->film_point.x, 330, 1e-9);
  EXPECT_NEAR(f->film_point.y, 219.2, 1e-9);
  EXPECT_NEAR(f->depth_m, 5, 1e-12);
}

TEST(ColmapModel, RotatedImageWithRadialDistortion) {
  Camera c = camera_of("side.jpg");
  // q = (cos 45°, 0, sin 45°, 0): R turns +Z of the world into … x_cam = R·X with
  // R = [0 0 1; 0 1 0; −1 0 0]; X = (−3, 0.3, 0.6) gives x_cam = (0.6, 0.3, 3).
  // SIMPLE_RADIAL: (x, y) = (0.2, 0.1), r² = 0.05, factor 1 − 0.1·0.05 = 0.995,
  // u = 700·0.199 + 400 = 539.3, v = 700·0.0995 + 300 = 369.65.
  std::optional<FilmProjection> f = c.project({-3, 0.3, 0.6});
  ASSERT_TRUE(f);
  EXPECT_NEAR(f->film_point.x, 539.3, 1e-9);
  EXPECT_NEAR(f->film_point.y, 369.65, 1e-9);
}

TEST(ColmapModel, CamerasWithoutImagesHaveNoPose) {
  CameraCalibration c = parse_colmap_model(kCameras, "cameras.txt", nullptr, "", "");
  EXPECT_FALSE(c.world_from_camera);
  EXPECT_EQ(c.projection.k.fy, 520);
}

TEST(ColmapModel, MistakesNameTheFileLineAndField) {
  struct Case {
    std::string cameras, images, image, expected;
  } cases[] = {
      {"1 PINHOLE 640 480 500 520 320\n", "", "",
       "cameras.txt:1: PINHOLE expects 4 parameters; got 3"},
      {"# c\n1 FOV 640 480 500 500 320 240 0.9\n", "", "", "cameras.txt:2: MODEL: expected"},
      {"1 PINHOLE 0 480 500 500 320 240\n", "", "",
       "cameras.txt:1: WIDTH: expected a whole number"},
      {"1 PINHOLE 640 480 500 nan 320 240\n", "", "", "PARAMS[1]: expected a finite number"},
      {"1 PINHOLE 640 480 -5 500 320 240\n", "", "", "cameras.txt:1"},
      {"1 PINHOLE 640 480 500 500 320 240\n1 PINHOLE 640 480 500 500 320 240\n", "", "",
       "cameras.txt:2: CAMERA_ID 1 appears twice"},
      {"", "", "", "cameras.txt: no camera"},
      {"1 PINHOLE 640 480 500 500 320 240\n", "1 0 0 0 0 0 0 5 1 a.jpg\n\n", "",
       "images.txt:1: QW QX QY QZ: expected a rotation quaternion"},
      {"1 PINHOLE 640 480 500 500 320 240\n", "1 1 0 0 0 0 0 5 9 a.jpg\n\n", "",
       "images.txt:1: CAMERA_ID 9 is not in cameras.txt"},
      {"1 PINHOLE 640 480 500 500 320 240\n", "1 1 0 0 0 0 0 5 1 a.jpg\n\n", "b.jpg",
       "no image named 'b.jpg'; its images: a.jpg"},
      {"1 PINHOLE 640 480 500 500 320 240\n", "1 1 0 0 0 0 5 1 a.jpg\n\n", "",
       "images.txt:1: expected IMAGE_ID QW QX QY QZ TX TY TZ CAMERA_ID NAME"},
  };
  for (const Case& c : cases) {
    try {
      parse_colmap_model(c.cameras, "cameras.txt", c.images.empty() ? nullptr : &c.images,
                         "images.txt", c.image);
      ADD_FAILURE() << "accepted: " << c.cameras << c.images;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(c.expected), std::string::npos)
          << e.what() << "\nexpected: " << c.expected;
    }
  }
}

TEST(ColmapModel, WritesOpenCvCxPlusHalfAPixel) {
  CameraCalibration c;
  c.projection.k = {.fx = 500, .fy = 510, .cx = 319.5, .cy = 239.5};
  c.projection.width_px = 640;
  c.projection.height_px = 480;
  c.image_name = "my shot.png";
  ColmapModelText text = colmap_model_text(c);
  EXPECT_NE(text.cameras.find("\n1 PINHOLE 640 480 500 510 320 240\n"), std::string::npos)
      << text.cameras;
  EXPECT_NE(text.images.find("\n1 1 0 0 0 0 0 0 1 my_shot.png\n\n"), std::string::npos)
      << text.images;
}

}  // namespace
}  // namespace obscura
