// `obscura camera` with a lens system, as a user runs it: the fitted camera is printed with its
// residuals and illumination, and --export writes it as a calibration the loader reads back.
#include <gtest/gtest.h>

#include "obscura/io/calibration_file.h"
#include "run_command.h"

namespace obscura {
namespace {

bool contains(const std::string& text, const std::string& piece) {
  return text.find(piece) != std::string::npos;
}

TEST(LensSystemCameraCli, PrintsTheFittedCamera) {
  auto result = test::run_cli("camera --lens double-gauss-50mm --width 360 --height 240");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  for (const char* line :
       {"fitted camera   opencv:-0.0", "fitted K        [", "centre          ", "fitted field    ",
        "fit residuals   distortion max ", "illumination    relative to the thin lens at f/2.03"})
    EXPECT_TRUE(contains(result.output, line)) << line << "\n" << result.output;
  auto fisheye = test::run_cli("camera --lens fisheye-10mm --width 360 --height 240");
  ASSERT_EQ(fisheye.exit_code, 0) << fisheye.output;
  EXPECT_TRUE(contains(fisheye.output, "fitted camera   kannala-brandt:")) << fisheye.output;
  EXPECT_TRUE(contains(fisheye.output, "field limited to 76.")) << fisheye.output;
}

TEST(LensSystemCameraCli, ExportsTheFittedCalibration) {
  auto result = test::run_cli(
      "camera --lens double-gauss-50mm --width 360 --height 240 --export opencv-yaml");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  CameraCalibration c = parse_calibration_text(result.output, "stdout", "");
  EXPECT_EQ(c.projection.width_px, 360);
  EXPECT_TRUE(std::holds_alternative<PinholeDistortion>(c.projection.lens));
  EXPECT_LT(std::get<PinholeDistortion>(c.projection.lens).k1, 0);  // barrel
  EXPECT_TRUE(c.world_from_camera.has_value());
}

}  // namespace
}  // namespace obscura
