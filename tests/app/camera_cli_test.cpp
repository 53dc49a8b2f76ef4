// `obscura camera` and the camera overrides of `obscura render`, run as a user would.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "obscura/io/image_io.h"
#include "run_command.h"
#include "test_paths.h"

namespace obscura {
namespace {

namespace fs = std::filesystem;

bool contains(const std::string& text, const std::string& piece) {
  return text.find(piece) != std::string::npos;
}

TEST(CameraCli, PrintsTheCornellCameraInEveryVocabulary) {
  auto result = test::run_cli("camera");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  // The published camera: 35 mm on 25 mm film, 2·atan(12.5/35) = 39.3076° both ways.
  EXPECT_TRUE(contains(result.output, "39.3076° horizontal, 39.3076° vertical")) << result.output;
  EXPECT_TRUE(contains(result.output, "35 mm on a 25 x 25 mm sensor")) << result.output;
  // fx = f·W / sensor = 35 · 512 / 25 = 716.8; centred principal point (W − 1)/2 = 255.5.
  EXPECT_TRUE(contains(result.output, "[716.8 0 255.5; 0 716.8 255.5; 0 0 1]")) << result.output;
  EXPECT_TRUE(contains(result.output, "yfov 0.686048 rad")) << result.output;
  EXPECT_TRUE(contains(result.output, "aspectRatio 1,")) << result.output;
  EXPECT_TRUE(contains(result.output, "lens 35 mm, sensor 25 x 25 mm, fit AUTO")) << result.output;
  EXPECT_TRUE(contains(result.output, "near 0.1 m, far 1000 m")) << result.output;
}

TEST(CameraCli, OverridesResolveLikeAPhotographersCamera) {
  auto result = test::run_cli(
      "camera cornell-box --camera cornell --focal-length 50 --sensor 36x24 --width 360 "
      "--height 240");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_TRUE(contains(result.output, "39.5978° horizontal")) << result.output;  // published
  EXPECT_TRUE(contains(result.output, "[500 0 179.5; 0 500 119.5; 0 0 1]")) << result.output;
  auto lens = test::run_cli("camera --fstop 2 --aperture-blades 6 --iso 200 --shutter 0:1/50");
  ASSERT_EQ(lens.exit_code, 0) << lens.output;
  // 35 mm at f/2: a 17.5 mm aperture, lens radius 8.75 mm.
  EXPECT_TRUE(contains(lens.output, "thin lens f/2, aperture 17.5 mm (6 blades")) << lens.output;
  EXPECT_TRUE(contains(lens.output, "lens radius 0.00875 m")) << lens.output;
  // EV100 = log2(2² · 50 · 100/200) = log2(100) = 6.64386.
  EXPECT_TRUE(contains(lens.output, "physical: ISO 200, EV100 6.64386")) << lens.output;
  EXPECT_TRUE(contains(lens.output, "DOF on")) << lens.output;
  auto fisheye = test::run_cli("camera --projection fisheye --fov 200");
  ASSERT_EQ(fisheye.exit_code, 0) << fisheye.output;
  EXPECT_TRUE(contains(fisheye.output, "FISHEYE_EQUIDISTANT, fisheye_fov 200°")) << fisheye.output;
  EXPECT_TRUE(contains(fisheye.output, "glTF has no fisheye camera")) << fisheye.output;
}

TEST(CameraCli, APhysicalSensorFitsAsBlenderWhateverTheSceneFit) {
  // The reference Cornell glb's camera is a glTF yfov (a vertical fit). Given a lens and a sensor,
  // Blender's AUTO fit applies: on a square image the 36 mm width spans it, 2·atan(18/50).
  auto result = test::run_cli("camera " + test::source_path("data/reference/cornell/cornell.glb") +
                              " --width 128 --height 128 --focal-length 50 --sensor 36x24"
                              " --fstop 0.25 --focus-distance 3.4 --focus-breathing off");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_TRUE(contains(result.output, "39.5978° horizontal, 39.5978° vertical")) << result.output;
  EXPECT_TRUE(contains(result.output, "image distance  50 mm")) << result.output;
  // With breathing (the default) the sensor sits at v = 50 · 3400 / 3350 = 50.7463 mm.
  auto breathing =
      test::run_cli("camera " + test::source_path("data/reference/cornell/cornell.glb") +
                    " --focal-length 50 --sensor 36x24 --fstop 0.25"
                    " --focus-distance 3.4");
  ASSERT_EQ(breathing.exit_code, 0) << breathing.output;
  EXPECT_TRUE(contains(breathing.output, "image distance  50.7463 mm")) << breathing.output;
}

struct BadCall {
  const char* arguments;
  int exit_code;
  const char* message;
};

class CameraCliErrors : public ::testing::TestWithParam<BadCall> {};

TEST_P(CameraCliErrors, NameTheOptionAndTheValue) {
  auto result = test::run_cli(GetParam().arguments);
  EXPECT_EQ(result.exit_code, GetParam().exit_code) << result.output;
  EXPECT_TRUE(contains(result.output, GetParam().message)) << result.output;
  EXPECT_TRUE(contains(result.output, "error")) << result.output;
}

INSTANTIATE_TEST_SUITE_P(
    Camera, CameraCliErrors,
    ::testing::Values(
        BadCall{"camera --fov 0", 2, "vertical_fov_degrees: must be in (0, 180) degrees; got 0"},
        BadCall{"camera --fov 180", 2, "got 180"},
        BadCall{"camera --focal-length -5", 2,
                "--focal-length: expected a number from 0 to 1e+06; got '-5'"},
        BadCall{"camera --sensor 36x0", 2, "sensor_height_mm: must be positive; got 0"},
        BadCall{"camera --sensor 36", 2, "--sensor expects WxH"},
        BadCall{"camera --near 0", 2, "near_m: must be positive; got 0"},
        BadCall{"camera --near 5 --far 2", 2, "far_m: must exceed near"},
        BadCall{"camera --fstop 0", 2, "f_number: must be positive; got 0"},
        BadCall{"camera --fstop 2 --focus-breathing maybe", 2,
                "--focus-breathing expects on or off; got 'maybe'"},
        BadCall{"camera --focus-distance -1", 2,
                "--focus-distance: expected a number from 0 to 1e+12; got '-1'"},
        BadCall{"camera --width 0", 2, "--width: expected an integer from 1 to 65536; got '0'"},
        BadCall{"camera --crop 0,0,1.5,1", 2, "crop: must lie within [0, 1]"},
        BadCall{"camera --crop 0,0,1", 2, "--crop expects x0,y0,x1,y1"},
        BadCall{"camera --shutter 1:0", 2, "close must be at or after open"},
        BadCall{"camera --shutter 0:1/0", 2, "--shutter expects a number"},
        BadCall{"camera --projection cylinder", 2, "got 'cylinder'"},
        BadCall{"camera --projection orthographic --fstop 2", 2, "applies to a perspective camera"},
        BadCall{"camera --filter lanczos", 2, "lanczos"},
        BadCall{"camera --camera nope", 1, "no camera 'nope'"},
        BadCall{"render --fov 0 -o /tmp/never-written.png", 2, "vertical_fov_degrees"}),
    [](const ::testing::TestParamInfo<BadCall>& info) {
      return "case" + std::to_string(info.index);
    });

class RenderCameraCli : public test::TempDirTest {
 protected:
  Image render(const std::string& arguments, const std::string& name) {
    auto result = test::run_cli("render -q --spp 2 --seed 3 " + arguments + " -o " + path(name));
    EXPECT_EQ(result.exit_code, 0) << result.output;
    return read_image(path(name));
  }
};

TEST_F(RenderCameraCli, CropRendersExactlyThatRegionOfTheFullImage) {
  Image full = render("--width 40 --height 30", "full.exr");
  Image crop = render("--width 40 --height 30 --crop 0.25,0.5,0.75,1", "crop.exr");
  ASSERT_EQ(crop.width, 20);
  ASSERT_EQ(crop.height, 15);
  for (int y = 0; y < 15; ++y)
    for (int x = 0; x < 20; ++x)
      for (int c = 0; c < 3; ++c) ASSERT_EQ(crop.at(x, y, c), full.at(x + 10, y + 15, c));
}

TEST_F(RenderCameraCli, ExposureCompensationAndIsoScaleTheImage) {
  Image base = render("--width 16 --height 16", "base.exr");
  Image brighter = render("--width 16 --height 16 --exposure 1", "plus1.exr");
  Image iso100 = render("--width 16 --height 16 --iso 100 --fstop 16", "iso100.exr");
  Image iso200 = render("--width 16 --height 16 --iso 200 --fstop 16", "iso200.exr");
  for (size_t i = 0; i < base.data.size(); ++i) {
    EXPECT_EQ(brighter.data[i], 2 * base.data[i]);  // ×2 is exact in floating point
    EXPECT_NEAR(iso200.data[i], 2 * iso100.data[i], 1e-6f * (1 + iso200.data[i]));
  }
}

TEST_F(RenderCameraCli, FisheyeLeavesTheCornersBlack) {
  Image image = render("--width 32 --height 32 --projection fisheye", "fisheye.exr");
  EXPECT_EQ(image.rgb(0, 0).r, 0);
  EXPECT_EQ(image.rgb(31, 31).g, 0);
  EXPECT_GT(image.rgb(16, 16).r + image.rgb(16, 16).g, 0);
}

}  // namespace
}  // namespace obscura
