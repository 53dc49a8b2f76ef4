// The calibrated camera on the command line: --intrinsics, --distortion, --calibration and
// `obscura camera --export`, run as a user would, with their mistakes.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "run_command.h"

namespace obscura {
namespace {

namespace fs = std::filesystem;

using CalibratedCameraCli = test::TempDirTest;

bool contains(const std::string& text, const std::string& piece) {
  return text.find(piece) != std::string::npos;
}

std::string read(const std::string& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

TEST_F(CalibratedCameraCli, IntrinsicsAndDistortionMakeACalibratedCamera) {
  auto r = test::run_cli(
      "camera --width 640 --height 480 --intrinsics 500,510,300.25,250.5,0.5 "
      "--distortion opencv:-0.2,0.05,0.001,-0.002,0.01");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(contains(r.output, "projection      calibrated")) << r.output;
  EXPECT_TRUE(contains(r.output, "[500 0.5 300.25; 0 510 250.5; 0 0 1]")) << r.output;
  EXPECT_TRUE(contains(r.output, "opencv:-0.2,0.05,0.001,-0.002,0.01")) << r.output;
  // The pose stays: the Cornell camera at (0.278, 0.273, −0.8).
  EXPECT_TRUE(contains(r.output, "(0.278, 0.273, -0.8) m")) << r.output;
  // K given for 320 x 240 scales to the 640 x 480 film: fx 2·250, cx (159.5 + ½)·2 − ½ = 319.5.
  auto scaled = test::run_cli(
      "camera --width 640 --height 480 --intrinsics 250,250,159.5,119.5 "
      "--calibration-size 320x240 --distortion kannala-brandt:0.01,0,0,0 --max-field-angle 95");
  ASSERT_EQ(scaled.exit_code, 0) << scaled.output;
  EXPECT_TRUE(contains(scaled.output, "[500 0 319.5; 0 500 239.5; 0 0 1]")) << scaled.output;
  EXPECT_TRUE(contains(scaled.output, "field limited to 95°")) << scaled.output;
  // A perspective camera turned calibrated keeps its framing as K (the Cornell box's 716.8).
  auto kept = test::run_cli("camera --projection calibrated --distortion equisolid");
  ASSERT_EQ(kept.exit_code, 0) << kept.output;
  EXPECT_TRUE(contains(kept.output, "[716.8 0 255.5; 0 716.8 255.5; 0 0 1]")) << kept.output;
}

TEST_F(CalibratedCameraCli, ExportAndReimportEveryFormat) {
  std::string camera =
      "camera --width 320 --height 200 --intrinsics 300,290,150.25,99.75 "
      "--distortion opencv:-0.1,0.01,0.001,0.002,0.003";
  std::string reference = test::run_cli(camera).output;
  for (const char* format : {"opencv-yaml", "opencv-json", "nerf"}) {
    std::string file =
        path(std::string("cal.") + (std::string(format) == "opencv-yaml" ? "yaml" : "json"));
    auto e = test::run_cli(camera + " --export " + format + " --output " + file);
    ASSERT_EQ(e.exit_code, 0) << e.output;
    auto back = test::run_cli("camera --calibration " + file);
    ASSERT_EQ(back.exit_code, 0) << back.output;
    EXPECT_EQ(back.output, reference) << format;
    // Without --output the same text goes to stdout.
    auto printed = test::run_cli(camera + " --export " + format);
    EXPECT_EQ(printed.output, read(file)) << format;
  }
  auto colmap = test::run_cli(camera + " --export colmap --output " + path("model"));
  ASSERT_EQ(colmap.exit_code, 0) << colmap.output;
  EXPECT_TRUE(fs::exists(path("model/points3D.txt")));
  EXPECT_TRUE(
      contains(read(path("model/cameras.txt")),
               "1 FULL_OPENCV 320 200 300 290 150.75 100.25 -0.1 0.01 0.001 0.002 0.003 0 0 0"))
      << read(path("model/cameras.txt"));  // k3 needs FULL_OPENCV; cx, cy plus ½
  for (const char* model_path : {"model", "model/images.txt", "model/cameras.txt"}) {
    auto back = test::run_cli("camera --calibration " + path(model_path));
    ASSERT_EQ(back.exit_code, 0) << back.output;
    EXPECT_EQ(back.output, reference) << model_path;
  }
}

TEST_F(CalibratedCameraCli, MistakesNameTheOptionOrFile) {
  std::ofstream(path("bad.yaml")) << "%YAML:1.0\n---\nimage_width: 640\nimage_height: 480\n"
                                     "camera_matrix: !!opencv-matrix\n   rows: 3\n   cols: 3\n"
                                     "   dt: d\n   data: [ 500, 0, 320, 0, 500 ]\n";
  test::expect_refusals(
      "camera ",
      {
          {"--intrinsics 500,500,1", "--intrinsics expects fx,fy,cx,cy[,skew]"},
          {"--intrinsics 0,500,1,1", "--intrinsics: fx and fy must be positive"},
          {"--distortion opencv:1,2,3", "--distortion: opencv expects 4, 5, 8, 12 or 14"},
          {"--distortion fish", "unknown lens model 'fish'"},
          {"--distortion equidistant:0.1", "equidistant takes no coefficients"},
          {"--calibration-size 0x480", "--calibration-size expects whole numbers"},
          {"--max-field-angle 200", "--max-field-angle"},
          {"--projection spherical --distortion equisolid", "needs --intrinsics"},
          {"--calibration-image a.jpg", "--calibration-image 'a.jpg' needs --calibration"},
          {"--calibration " + path("missing.yaml"), "missing.yaml"},
          {"--calibration " + path("bad.yaml"), "bad.yaml:9: camera_matrix.data: expected 9"},
          {"--calibration " + path("bad.yaml") + " --calibration-image x", "holds one camera"},
          {"--export tiff", "--export expects opencv-yaml, opencv-json, colmap or nerf"},
          {"--export colmap", "give --output FOLDER"},
          {"--output x.yaml", "--output needs --export"},
          {"--projection orthographic --export opencv-yaml", "cannot describe its orthographic"},
          {"--distortion ftheta:1,0.1 --export colmap --output " + path("m"),
           "COLMAP has no ftheta lens model"},
      });
  EXPECT_FALSE(fs::exists(path("m/cameras.txt")));  // no partial output
  auto usage = test::run_cli("camera --intrinsics 1,2");
  EXPECT_EQ(usage.exit_code, 2) << usage.output;
  auto file = test::run_cli("camera --calibration " + path("bad.yaml"));
  EXPECT_EQ(file.exit_code, 1) << file.output;
}

}  // namespace
}  // namespace obscura
