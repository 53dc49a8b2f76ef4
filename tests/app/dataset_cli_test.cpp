// `obscura dataset`: COLMAP reads its model with every image registered, a resumed dataset
// renders only the views that are missing, MPI ranks write the same bytes as one process, and
// what a calibration format cannot hold is a warning naming it. Also the camera placement
// options (--position, --look-at, --up) of `render` and `camera`.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "mpi_launcher.h"
#include "run_command.h"

namespace obscura {
namespace {

namespace fs = std::filesystem;
using DatasetCli = test::TempDirTest;

const std::string kSmall = "dataset -q --width 32 --height 24 --spp 1 ";

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Every file under `folder`, by its relative path, with its bytes.
std::map<std::string, std::string> files_of(const std::string& folder) {
  std::map<std::string, std::string> out;
  for (const auto& entry : fs::recursive_directory_iterator(folder))
    if (entry.is_regular_file())
      out[fs::relative(entry.path(), folder).string()] = read_text(entry.path().string());
  return out;
}

TEST_F(DatasetCli, WritesOneModelNamingEveryImage) {
  auto r = test::run_cli(kSmall + "--views orbit:12 -o " + path("set"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto files = files_of(path("set"));
  for (int i = 0; i < 12; ++i) {
    char name[32];
    std::snprintf(name, sizeof name, "view_%04d", i);
    EXPECT_TRUE(files.count("images/" + std::string(name) + ".png")) << name;
    EXPECT_TRUE(files.count("opencv/" + std::string(name) + ".yaml")) << name;
    EXPECT_NE(files.at("sparse/0/images.txt").find(" 1 " + std::string(name) + ".png\n"),
              std::string::npos);
    EXPECT_NE(
        files.at("transforms.json").find("\"file_path\": \"images/" + std::string(name) + ".png\""),
        std::string::npos);
  }
  EXPECT_NE(files.at("sparse/0/cameras.txt").find("# Number of cameras: 1\n"), std::string::npos);
  // A view of the model reads back as the calibration of that image.
  auto back = test::run_cli("camera --calibration " + path("set/transforms.json") +
                            " --calibration-image images/view_0003.png");
  EXPECT_EQ(back.exit_code, 0) << back.output;
}

TEST_F(DatasetCli, ColmapRegistersEveryImage) {
  if (std::system("command -v colmap > /dev/null 2>&1") != 0)
    GTEST_SKIP() << "colmap is not installed (scripts/setup installs Debian's colmap)";
  auto r = test::run_cli(kSmall + "--views sphere:12 --formats colmap -o " + path("set"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  auto analyzed = test::run_shell("QT_QPA_PLATFORM=offscreen colmap model_analyzer --path " +
                                  path("set/sparse/0") + " 2>&1");
  ASSERT_EQ(analyzed.exit_code, 0) << analyzed.output;
  EXPECT_NE(analyzed.output.find("Registered images: 12"), std::string::npos) << analyzed.output;
  EXPECT_NE(analyzed.output.find("Cameras: 1"), std::string::npos) << analyzed.output;
}

TEST_F(DatasetCli, ResumingRendersOnlyTheMissingViews) {
  const std::string command =
      "dataset --width 32 --height 24 --spp 1 --views orbit:8 "
      "--ground-truth -o " +
      path("set");
  auto first = test::run_cli(command);
  ASSERT_EQ(first.exit_code, 0) << first.output;
  EXPECT_NE(first.output.find("8 rendered, 0 already there"), std::string::npos) << first.output;
  const auto before = files_of(path("set"));
  fs::remove(path("set/images/view_0002.png"));
  fs::remove(path("set/ground_truth/view_0005.exr"));
  // A damaged file is rendered again too.
  std::ofstream(path("set/images/view_0006.png"), std::ios::trunc) << "not a png";
  auto second = test::run_cli(command);
  ASSERT_EQ(second.exit_code, 0) << second.output;
  EXPECT_NE(second.output.find("3 rendered, 5 already there"), std::string::npos) << second.output;
  for (const char* view : {"view_0002", "view_0005", "view_0006"})
    EXPECT_NE(second.output.find(std::string(view) + " rendered"), std::string::npos) << view;
  EXPECT_EQ(files_of(path("set")), before);  // the same bytes again
}

TEST_F(DatasetCli, PathAndSceneCamerasAndRefusals) {
  std::ofstream(path("path.txt")) << "# x y z  tx ty tz\n0 1 4  0 1 0\n2 1 3  0 1 0\n";
  auto r = test::run_cli(kSmall + "--views path:3:" + path("path.txt") + " -o " + path("p"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(fs::exists(path("p/images/view_0002.png")));
  r = test::run_cli(kSmall + "--views cameras -o " + path("c"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(fs::exists(path("c/images/view_0000.png")));
  test::expect_refusals(kSmall + "-o " + path("x") + " ",
                        {{"--views orbit:0", "--views: the number of views"},
                         {"--views spiral:3", "--views expects orbit:N"},
                         {"--views orbit:3:95", "elevation"},
                         {"--views orbit:3 --position 1,2,3", "--position, --look-at and --up"},
                         {"--views orbit:3 --projection orthographic", "field of view"},
                         {"--views orbit:3 --formats colmap,ply", "--formats expects"},
                         {"--views orbit:3 --projection fisheye", "--formats"},
                         {"--views path:3:" + path("missing.txt"), "missing.txt"},
                         {"--views orbit:3 --crop 0,0,0.5,0.5", "whole frames"},
                         {"--views orbit:3 --time-limit 1", "--time-limit"}});
}

TEST_F(DatasetCli, FieldLimitsColmapAndNerfCannotHoldAreWarnings) {
  const std::string fisheye =
      "--projection calibrated --intrinsics 10,10,15.5,11.5 --distortion kannala-brandt:0,0,0,0 "
      "--max-field-angle 95";
  auto r = test::run_cli(kSmall + "--views orbit:2 " + fisheye + " -o " + path("f"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("COLMAP cannot hold the fisheye's 190° field limit"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("NeRF's transforms.json cannot hold the fisheye's 190° field limit"),
            std::string::npos)
      << r.output;
  // The OpenCV file keeps it.
  EXPECT_NE(read_text(path("f/opencv/view_0000.yaml")).find("max_field_angle_degrees"),
            std::string::npos);
  auto e = test::run_cli("camera --width 32 --height 24 " + fisheye + " --export nerf");
  EXPECT_EQ(e.exit_code, 0) << e.output;
  EXPECT_NE(e.output.find("warning: NeRF's transforms.json cannot hold the fisheye's 190°"),
            std::string::npos)
      << e.output;
}

TEST_F(DatasetCli, PlacementOptionsPlaceTheCamera) {
  auto placed = test::run_cli("camera --position 0,1,5 --look-at 0,1,0 --export nerf");
  ASSERT_EQ(placed.exit_code, 0) << placed.output;
  EXPECT_NE(placed.output.find("[1, 0, 0, 0],\n        [0, 1, 0, 1],\n        [0, 0, 1, 5]"),
            std::string::npos)
      << placed.output;
  auto rolled = test::run_cli("camera --position 0,0,0 --look-at 0,0,-1 --up 1,0,0 --export nerf");
  ASSERT_EQ(rolled.exit_code, 0) << rolled.output;
  EXPECT_NE(rolled.output.find("[0, 1, 0, 0],\n        [-1, 0, 0, 0]"), std::string::npos)
      << rolled.output;
  auto render = test::run_cli(
      "render -q --width 16 --height 12 --spp 1 --position 0,1,4 "
      "--look-at 0,1,0 -o " +
      path("r.png"));
  EXPECT_EQ(render.exit_code, 0) << render.output;
  test::expect_refusals("camera ", {{"--position 1,2,3 --look-at 1,2,3", "the camera's position"},
                                    {"--look-at 0,5,0 --position 0,0,0 --up 0,1,0", "parallel"},
                                    {"--up 0,0,0", "zero length"},
                                    {"--position 1,nan,3", "--position"},
                                    {"--look-at 1,2", "X,Y,Z"}});
}

using DatasetMpi = test::MpiCliTest;

TEST_F(DatasetMpi, RanksWriteTheSameBytesAsOneProcess) {
  const std::string options =
      "dataset -q --width 32 --height 24 --spp 2 --views orbit:5 "
      "--ground-truth --aovs -o ";
  auto runs = test::run_shells_concurrently(
      {test::cli_command_line(options + path("one")), mpirun_obscura(3, options + path("three"))});
  ASSERT_EQ(runs[0].exit_code, 0) << runs[0].output;
  ASSERT_EQ(runs[1].exit_code, 0) << runs[1].output;
  const auto one = files_of(path("one")), three = files_of(path("three"));
  // Per view: the image, 5 AOVs (albedo, normal, depth, range, id), ground truth; the model
  // (3 COLMAP files, transforms.json); 5 OpenCV files.
  EXPECT_EQ(one.size(), 5u * 7 + 3 + 1 + 5);
  ASSERT_EQ(one.size(), three.size());
  for (const auto& [name, bytes] : one) EXPECT_TRUE(three.at(name) == bytes) << name;
}

}  // namespace
}  // namespace obscura
