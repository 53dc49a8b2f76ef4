// The calibrated camera of the JSON scene file: its keys arrive in the camera, K projects as
// OpenCV's pinhole model says, and mistakes name the file and the JSON path.
#include <gtest/gtest.h>

#include "obscura/io/json_scene.h"
#include "obscura/math/error.h"

namespace obscura {
namespace {

Scene load(const std::string& camera) {
  return load_json_scene_text(
      R"({"render": {"width": 640, "height": 480}, "cameras": [)" + camera + "]}", "scene.json");
}

TEST(CalibratedCameraJson, KeysArriveInTheCamera) {
  Scene s = load(R"({"type": "calibrated", "position": [0, 0, 0], "target": [0, 0, -1],
    "intrinsics": {"fx": 500, "fy": 520, "cx": 319.5, "cy": 239.5, "skew": 0.25,
                   "width": 640, "height": 480},
    "lens": {"model": "opencv", "coefficients": [-0.2, 0.05, 0.001, -0.002]},
    "max_field_angle_degrees": 60})");
  const auto& p = std::get<CalibratedProjection>(s.camera.projection);
  EXPECT_EQ(p.k.fy, 520);
  EXPECT_EQ(p.k.skew, 0.25);
  EXPECT_EQ(p.width_px, 640);
  EXPECT_EQ(std::get<PinholeDistortion>(p.lens).p2, -0.002);
  EXPECT_EQ(p.max_field_angle_degrees, 60);
  // Without distortion: (X, Y, Z) = (0.2, 0.1, 2) in OpenCV's frame is u = 500·0.1 + 0.25·0.05 +
  // 319.5 = 369.5125, v = 520·0.05 + 239.5 = 265.5; Obscura's frame negates Y and Z, raster = u +
  // ½.
  Scene pinhole = load(R"({"type": "calibrated", "position": [0, 0, 0], "target": [0, 0, -1],
    "intrinsics": {"fx": 500, "fy": 520, "cx": 319.5, "cy": 239.5, "skew": 0.25}})");
  std::optional<FilmProjection> f = pinhole.camera.project({0.2, -0.1, -2});
  ASSERT_TRUE(f);
  EXPECT_NEAR(f->film_point.x, 370.0125, 1e-9);
  EXPECT_NEAR(f->film_point.y, 266, 1e-9);
  Scene fisheye = load(R"({"type": "calibrated", "intrinsics": {"fx": 200, "fy": 200, "cx": 319.5,
    "cy": 239.5}, "lens": {"model": "equisolid"}})");
  EXPECT_TRUE(std::holds_alternative<ClassicFisheye>(
      std::get<CalibratedProjection>(fisheye.camera.projection).lens));
}

TEST(CalibratedCameraJson, MistakesNameThePath) {
  struct Case {
    std::string camera, expected;
  } cases[] = {
      {R"({"type": "calibrated"})", "$.cameras[0].intrinsics: a calibrated camera needs"},
      {R"({"type": "calibrated", "intrinsics": {"fx": 5, "fy": 5, "cx": 1}})",
       "$.cameras[0].intrinsics.cy: missing"},
      {R"({"type": "calibrated", "intrinsics": {"fx": -5, "fy": 5, "cx": 1, "cy": 1}})",
       "$.cameras[0].intrinsics.fx: expected a number in"},
      {R"({"type": "calibrated", "intrinsics": {"fx": 5, "fy": 5, "cx": 1, "cy": 1, "f": 2}})",
       "'f'"},
      {R"({"type": "calibrated", "intrinsics": {"fx": 5, "fy": 5, "cx": 1, "cy": 1, "width": 6}})",
       "$.cameras[0].intrinsics.height: give both width and height"},
      {R"({"type": "calibrated", "intrinsics": {"fx": 5, "fy": 5, "cx": 1, "cy": 1},
          "lens": {"model": "opencv", "coefficients": [1, 2, 3]}})",
       "$.cameras[0].lens.coefficients: opencv expects 4, 5, 8, 12 or 14"},
      {R"({"type": "calibrated", "intrinsics": {"fx": 5, "fy": 5, "cx": 1, "cy": 1},
          "lens": {"model": "fish"}})",
       "$.cameras[0].lens.model: unknown lens model 'fish'"},
      {R"({"type": "calibrated", "intrinsics": {"fx": 5, "fy": 5, "cx": 1, "cy": 1},
          "max_field_angle_degrees": 181})",
       "$.cameras[0].max_field_angle_degrees"},
      {R"({"type": "calibrated", "intrinsics": {"fx": 5, "fy": 5, "cx": 1, "cy": 1},
          "lens": {"model": "equidistant", "k": 1}})",
       "'k'"},
  };
  for (const Case& c : cases) {
    try {
      load(c.camera);
      ADD_FAILURE() << "accepted: " << c.camera;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(c.expected), std::string::npos)
          << e.what() << "\nexpected: " << c.expected;
      EXPECT_NE(std::string(e.what()).find("scene.json"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace obscura
