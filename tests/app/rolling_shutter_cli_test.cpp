// --rolling-shutter on the command line: both renderers draw with it, `obscura camera` reports
// it, the ground truth records it, and malformed values are usage errors naming the option.
#include <gtest/gtest.h>

#include <filesystem>

#include "run_command.h"

namespace obscura {
namespace {

using RollingShutterCli = test::TempDirTest;

bool contains(const std::string& text, const std::string& piece) {
  return text.find(piece) != std::string::npos;
}

TEST_F(RollingShutterCli, BothRenderersDrawItAndTheCameraReportsIt) {
  auto camera =
      test::run_cli("camera --width 64 --height 48 --rolling-shutter 1/4800:bottom-to-top");
  ASSERT_EQ(camera.exit_code, 0) << camera.output;
  // 48 lines read 1/4800 s apart: the last one starts 47/4800 s after the first.
  EXPECT_TRUE(contains(camera.output, "bottom-to-top")) << camera.output;
  EXPECT_TRUE(contains(camera.output, "0.0264583")) << camera.output;  // 1/60 + 47/4800
  for (const char* renderer : {"path", "raster"}) {
    std::string out = path(std::string(renderer) + ".exr");
    auto r = test::run_cli(std::string("render motion-blur --renderer ") + renderer +
                           " --width 48 --height 32 --spp 2 --rolling-shutter 1/2000 -o " + out);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_TRUE(std::filesystem::exists(out));
    if (std::string(renderer) == "raster") {
      EXPECT_TRUE(contains(r.output, "rolling shutter")) << r.output;  // says it draws bands
    }
  }
}

TEST_F(RollingShutterCli, MalformedValuesAreUsageErrors) {
  for (const char* value : {"fast", "-1/100", "2", "1/1000:sideways", "1/1000:"}) {
    auto r = test::run_cli(std::string("camera --rolling-shutter ") + value);
    EXPECT_EQ(r.exit_code, 2) << value << ": " << r.output;
    EXPECT_TRUE(contains(r.output, "--rolling-shutter")) << r.output;
    EXPECT_FALSE(contains(r.output, "terminate")) << r.output;
  }
}

TEST_F(RollingShutterCli, RasterGroundTruthRefusesARollingShutterAndNamesTheTracer) {
  auto r = test::run_cli(
      "render cornell-box --renderer raster --width 32 --height 32 "
      "--rolling-shutter 1/2000 --ground-truth " +
      path("gt.exr") + " -o " + path("img.png"));
  EXPECT_NE(r.exit_code, 0);
  EXPECT_TRUE(contains(r.output, "--renderer path")) << r.output;
  EXPECT_FALSE(std::filesystem::exists(path("img.png")));
}

}  // namespace
}  // namespace obscura
