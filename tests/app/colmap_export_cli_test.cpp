// COLMAP itself reads `obscura camera --export colmap` (Debian's colmap package, when installed;
// skipped otherwise): `colmap model_converter` rewrites the model, and the cameras it writes read
// back into the same camera.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "run_command.h"

namespace obscura {
namespace {

using ColmapExportCli = test::TempDirTest;

TEST_F(ColmapExportCli, ColmapReadsOurModelAndWeReadColmaps) {
  if (std::system("command -v colmap > /dev/null 2>&1") != 0)
    GTEST_SKIP() << "colmap is not installed (apt-get install colmap)";
  std::string camera =
      "camera --width 320 --height 200 --intrinsics 300,290,150.25,99.75 "
      "--distortion opencv:-0.1,0.01,0.001,0.002";
  std::string reference = test::run_cli(camera).output;
  auto e = test::run_cli(camera + " --export colmap --output " + path("ours"));
  ASSERT_EQ(e.exit_code, 0) << e.output;
  std::filesystem::create_directories(path("theirs"));
  auto converted =
      test::run_shell("QT_QPA_PLATFORM=offscreen colmap model_converter --input_path " +
                      path("ours") + " --output_path " + path("theirs") + " --output_type TXT");
  ASSERT_EQ(converted.exit_code, 0) << converted.output;
  auto back = test::run_cli("camera --calibration " + path("theirs"));
  ASSERT_EQ(back.exit_code, 0) << back.output;
  EXPECT_EQ(back.output, reference);
}

}  // namespace
}  // namespace obscura
