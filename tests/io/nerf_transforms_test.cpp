// NeRF's transforms.json, written by hand as the original NeRF, instant-ngp and nerfstudio files
// are: camera → world in OpenGL's camera frame, cx, cy measured from the top-left corner (the
// image centre when absent), so that they equal Obscura's raster coordinates.
#include "obscura/io/nerf_transforms.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "obscura/math/error.h"

namespace obscura {
namespace {

Camera camera_of(const std::string& json, const std::string& image = "") {
  Camera camera;
  apply_calibration(camera, parse_nerf_transforms(json, "transforms.json", image));
  return camera;
}

const char* kIdentityAt4 = R"([[1,0,0,0],[0,1,0,0],[0,0,1,4],[0,0,0,1]])";

TEST(NerfTransforms, OriginalNerfFileWithCameraAngleX) {
  std::string json = std::string(R"({"camera_angle_x": 0.6911112070083618, "w": 800, "h": 800,
    "frames": [{"file_path": "./train/r_0", "transform_matrix": )") +
                     kIdentityAt4 + "}]}";
  Camera c = camera_of(json);
  // fl = 400 / tan(0.3455556): the point (0.5, 0.25, 0) is 4 m in front, (0.125, 0.0625) in
  // tangents, right and up of the image centre (400, 400).
  double fl = 400 / std::tan(0.6911112070083618 / 2);
  std::optional<FilmProjection> f = c.project({0.5, 0.25, 0});
  ASSERT_TRUE(f);
  EXPECT_NEAR(f->film_point.x, 400 + fl * 0.125, 1e-9);
  EXPECT_NEAR(f->film_point.y, 400 - fl * 0.0625, 1e-9);
}

TEST(NerfTransforms, ExplicitIntrinsicsPerFrameAndByName) {
  std::string json = std::string(R"({"fl_x": 1000, "fl_y": 1100, "cx": 410, "cy": 390,
    "w": 800, "h": 600, "aabb_scale": 16, "frames": [
      {"file_path": "images/a.png", "transform_matrix": )") +
                     kIdentityAt4 + R"(},
      {"file_path": "images/b.png", "fl_x": 2000, "transform_matrix": )" +
                     kIdentityAt4 + "}]}";
  Camera a = camera_of(json);
  std::optional<FilmProjection> f = a.project({0.5, 0.25, 0});
  ASSERT_TRUE(f);
  EXPECT_NEAR(f->film_point.x, 410 + 1000 * 0.125, 1e-9);
  EXPECT_NEAR(f->film_point.y, 390 - 1100 * 0.0625, 1e-9);
  EXPECT_EQ(std::get<CalibratedProjection>(a.projection).k.cx, 409.5);
  Camera b = camera_of(json, "b");  // by stem
  f = b.project({0.5, 0.25, 0});
  ASSERT_TRUE(f);
  EXPECT_NEAR(f->film_point.x, 410 + 2000 * 0.125, 1e-9);
  EXPECT_NO_THROW(camera_of(json, "images/b.png"));
  EXPECT_NO_THROW(camera_of(json, "b.png"));
}

TEST(NerfTransforms, FisheyeModelIsKannalaBrandt) {
  std::string json = std::string(R"({"camera_model": "OPENCV_FISHEYE", "fl_x": 300, "fl_y": 300,
    "cx": 320, "cy": 240, "w": 640, "h": 480, "k1": 0.05, "k2": 0.01, "k3": 0, "k4": 0,
    "frames": [{"file_path": "f.png", "transform_matrix": )") +
                     kIdentityAt4 + "}]}";
  Camera c = camera_of(json);
  // A point 45° off axis to the right: θ = π/4, θd = θ(1 + 0.05θ² + 0.01θ⁴).
  double theta = std::acos(-1.0) / 4;
  double t2 = theta * theta, thetad = theta * (1 + 0.05 * t2 + 0.01 * t2 * t2);
  std::optional<FilmProjection> f = c.project({1, 0, 3});
  ASSERT_TRUE(f);
  EXPECT_NEAR(f->film_point.x, 320 + 300 * thetad, 1e-9);
  EXPECT_NEAR(f->film_point.y, 240, 1e-9);
}

TEST(NerfTransforms, MistakesNameTheFileAndPath) {
  struct Case {
    std::string json, expected;
  } cases[] = {
      {R"({"camera_angle_x": 0.7, "frames": []})", "missing \"w\""},
      {R"({"w": 8, "h": 8, "frames": []})", "missing the focal length"},
      {R"({"fl_x": "big", "w": 8, "h": 8})", "$.fl_x: expected a finite number"},
      {R"({"fl_x": 5, "w": 8, "h": 8, "camera_model": "FOV"})", "$.camera_model: expected"},
      {R"({"fl_x": 5, "w": 8, "h": 8, "k4": 0.1})", "k4 is not part of OpenCV's pinhole model"},
      {R"({"fl_x": 5, "w": 8, "h": 8, "frames": [{"file_path": "a"}]})",
       "$.frames[0]: missing transform_matrix"},
      {R"({"fl_x": 5, "w": 8, "h": 8, "frames": [{"file_path": "a", "transform_matrix":
         [[1,0,0,0],[0,1,0,0],[0,0,1,0]]}]})",
       "$.frames[0].transform_matrix: expected a 4x4 array"},
      {R"({"fl_x": 5, "w": 8, "h": 8, "frames": [{"file_path": "a", "transform_matrix":
         [[2,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]]}]})",
       "not orthonormal"},
      {R"({"fl_x": 5, "w": 8, "h": 8, "frames": 3})", "$.frames: expected an array"},
      {R"({"fl_x": 5, "w": 8, "h": 8, "frames": [{"file_path": "a", "transform_matrix":
         [[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]]}]})",
       ""},
  };
  for (const Case& c : cases) {
    if (c.expected.empty()) {
      EXPECT_NO_THROW(parse_nerf_transforms(c.json, "t.json", ""));
      EXPECT_THROW(parse_nerf_transforms(c.json, "t.json", "zzz"), Error);
      continue;
    }
    try {
      parse_nerf_transforms(c.json, "t.json", "");
      ADD_FAILURE() << "accepted: " << c.json;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(c.expected), std::string::npos)
          << e.what() << "\nexpected: " << c.expected;
      EXPECT_EQ(std::string(e.what()).rfind("t.json", 0), 0u) << e.what();
    }
  }
}

// A full field of view of π or more has no pinhole focal length: 6.3 rad once gave one that
// imaged nothing (a black frame, exit 0).
TEST(NerfTransforms, FieldOfViewOfPiOrMoreIsRefused) {
  auto parse = [](double angle) {
    std::string json = "{\"camera_angle_x\": " + std::to_string(angle) +
                       ", \"w\": 64, \"h\": 48, \"frames\": [{\"file_path\": \"a\", "
                       "\"transform_matrix\": [[1,0,0,0],[0,1,0,0],[0,0,1,4],[0,0,0,1]]}]}";
    try {
      parse_nerf_transforms(json, "transforms.json", "");
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("(accepted)");
  };
  EXPECT_EQ(parse(1.2), "(accepted)");
  for (double bad : {6.3, 3.1416, 0.0, -1.0})
    EXPECT_THAT(parse(bad), ::testing::AllOf(::testing::HasSubstr("transforms.json"),
                                             ::testing::HasSubstr("camera_angle_x")))
        << bad;
}

// A pose 2e18 m away once reached Embree, which aborts beyond ~1.8e18 (SIGABRT).
TEST(NerfTransforms, PositionBeyondTheCoordinateBoundIsRefusedWithTheFile) {
  std::string json = R"({"fl_x": 50, "w": 64, "h": 48, "frames": [{"file_path": "a",
    "transform_matrix": [[1,0,0,2e18],[0,1,0,0],[0,0,1,4],[0,0,0,1]]}]})";
  try {
    parse_nerf_transforms(json, "transforms.json", "");
    ADD_FAILURE() << "accepted";
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), ::testing::AllOf(::testing::HasSubstr("transforms.json"),
                                           ::testing::HasSubstr("camera position"),
                                           ::testing::HasSubstr("single-precision")));
  }
}

}  // namespace
}  // namespace obscura
