// The `obscura render` command line, run as a user would.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "obscura/io/image_io.h"
#include "run_command.h"

namespace obscura {
namespace {

namespace fs = std::filesystem;

class RenderCli : public test::TempDirTest {
 protected:
  bool directory_is_empty() const { return fs::is_empty(dir_); }
};

TEST_F(RenderCli, RendersTheCornellBoxWithWallsWhereTheyBelong) {
  // Direct light only: bounced light would tint the walls towards each other.
  auto result = test::run_cli("render --renderer direct --width 64 --height 64 --spp 4 -o " +
                              path("box.png"));
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find(path("box.png")), std::string::npos) << "prints where it wrote";
  EXPECT_NE(result.output.find("64x64"), std::string::npos) << "summary line";
  Image image = read_image(path("box.png"));
  ASSERT_EQ(image.width, 64);
  ASSERT_EQ(image.height, 64);
  // Seen from the published camera, the red wall is on the left and the green one on the right.
  for (int y = 20; y < 44; y += 4) {
    Rgb left = image.rgb(4, y), right = image.rgb(59, y);
    EXPECT_GT(left.r, 2 * left.g) << "left wall at row " << y;
    EXPECT_GT(left.r, 0.2f);
    EXPECT_GT(right.g, 1.5f * right.r) << "right wall at row " << y;
    EXPECT_GT(right.g, 0.2f);
  }
  // The light is the brightest thing in the picture, near the top centre (row 7 is its edge,
  // only partly covered; row 9 lies inside it).
  Rgb light = image.rgb(32, 9);
  EXPECT_GT(light.r, 0.99f);
}

TEST_F(RenderCli, SameSeedGivesBitIdenticalImagesForAnyThreadCount) {
  auto one = test::run_cli("render -q --width 48 --height 40 --spp 3 --seed 9 --threads 1 -o " +
                           path("one.exr"));
  auto two = test::run_cli("render -q --width 48 --height 40 --spp 3 --seed 9 --threads 2 -o " +
                           path("two.exr"));
  ASSERT_EQ(one.exit_code, 0) << one.output;
  ASSERT_EQ(two.exit_code, 0) << two.output;
  Image a = read_image(path("one.exr")), b = read_image(path("two.exr"));
  EXPECT_EQ(a.data, b.data);
  auto other_seed =
      test::run_cli("render -q --width 48 --height 40 --spp 3 --seed 10 -o " + path("three.exr"));
  ASSERT_EQ(other_seed.exit_code, 0) << other_seed.output;
  EXPECT_NE(read_image(path("three.exr")).data, a.data);
}

TEST_F(RenderCli, FormatFollowsTheExtension) {
  for (const char* name : {"a.png", "a.exr", "a.pfm"}) {
    auto result = test::run_cli("render -q --width 8 --height 6 --spp 1 -o " + path(name));
    ASSERT_EQ(result.exit_code, 0) << result.output;
    Image image = read_image(path(name));
    EXPECT_EQ(image.width, 8);
    EXPECT_EQ(image.height, 6);
  }
}

struct BadCall {
  const char* arguments;
  int exit_code;
  const char* message;  // a piece of the error that names the problem
};

class RenderCliErrors : public RenderCli, public ::testing::WithParamInterface<BadCall> {};

TEST_P(RenderCliErrors, ClearMessageNonZeroExitAndNoOutput) {
  const BadCall& bad = GetParam();
  std::string arguments = bad.arguments;
  size_t at = arguments.find("DIR");
  if (at != std::string::npos) arguments.replace(at, 3, dir_);
  auto result = test::run_cli(arguments);
  EXPECT_EQ(result.exit_code, bad.exit_code) << result.output;
  EXPECT_NE(result.output.find(bad.message), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("error"), std::string::npos) << result.output;
  EXPECT_TRUE(fs::is_empty(dir_)) << "a file was left behind";
}

INSTANTIATE_TEST_SUITE_P(
    Render, RenderCliErrors,
    ::testing::Values(BadCall{"render --bogus -o DIR/x.png", 2, "--bogus"},
                      BadCall{"render --width 0 -o DIR/x.png", 2,
                              "--width: expected an integer from 1 to 65536; got '0'"},
                      BadCall{"render --height -3 -o DIR/x.png", 2,
                              "--height: expected an integer from 1 to 65536; got '-3'"},
                      BadCall{"render --spp -1 -o DIR/x.png", 2,
                              "--spp: expected an integer from 1 to 1048576; got '-1'"},
                      BadCall{"render --spp many -o DIR/x.png", 2, "--spp"},
                      BadCall{"render -o DIR/no/such/dir/x.png", 1, "does not exist"},
                      BadCall{"render -o DIR", 1, "is a directory"},
                      BadCall{"render -o DIR/x.bmp", 1, "unsupported image extension '.bmp'"},
                      BadCall{"render no-such-scene -o DIR/x.png", 1, "no-such-scene"},
                      BadCall{"", 2, "subcommand"},
                      BadCall{"preview", 2, "unknown command 'preview'; the commands are render"}),
    [](const ::testing::TestParamInfo<BadCall>& info) {
      return "case" + std::to_string(info.index);
    });

TEST_F(RenderCli, AWebPageSavedAsGlbIsNamedForWhatItIsNot) {
  // What a download of a model's web page leaves: HTML under a .glb name.
  std::ofstream(path("model.glb")) << "<!DOCTYPE html>\n<html><head><title>Model</title>";
  auto result = test::run_cli("render " + path("model.glb") + " -q -o " + path("x.png"));
  EXPECT_EQ(result.exit_code, 1) << result.output;
  EXPECT_NE(result.output.find("not a glTF file"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("starts with \"<!DOCTYPE html>"), std::string::npos)
      << result.output;
  EXPECT_FALSE(fs::exists(path("x.png")));
}

TEST_F(RenderCli, UnwritableOutputIsReportedAndLeavesNothing) {
  // /proc takes no new files, even from root (who may write to any chmod-protected directory).
  auto result = test::run_cli("render -q --width 8 --height 8 --spp 1 -o /proc/obscura-cli.png");
  EXPECT_EQ(result.exit_code, 1) << result.output;
  EXPECT_NE(result.output.find("/proc/obscura-cli.png"), std::string::npos) << result.output;
  EXPECT_FALSE(fs::exists("/proc/obscura-cli.png"));
}

TEST_F(RenderCli, VersionHelpAndSceneList) {
  auto version = test::run_cli("--version");
  EXPECT_EQ(version.exit_code, 0);
  EXPECT_NE(version.output.find("obscura " OBSCURA_VERSION), std::string::npos) << version.output;
  auto help = test::run_cli("render --help");
  EXPECT_EQ(help.exit_code, 0);
  for (const char* flag :
       {"--output", "--width", "--height", "--spp", "--threads", "--seed", "--quiet"})
    EXPECT_NE(help.output.find(flag), std::string::npos) << flag;
  auto list = test::run_cli("render --scene-list");
  EXPECT_EQ(list.exit_code, 0);
  EXPECT_NE(list.output.find("cornell-box"), std::string::npos);
}

}  // namespace
}  // namespace obscura
