// The command line's outputs replace only regular files: a FIFO, a device or a symbolic link to
// one named by an output option is refused before rendering (exit 2, naming the option and the
// path) and left as it was; a frame and its ground truth are replaced together or not at all.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "io/mesh_test_files.h"
#include "run_command.h"

namespace obscura {
namespace {

namespace fs = std::filesystem;

class OutputTargetsCli : public test::TempDirTest {};

TEST_F(OutputTargetsCli, FifosDevicesAndLinksToThemAreRefusedByName) {
  ASSERT_EQ(::mkfifo(path("pipe.png").c_str(), 0600), 0);
  ASSERT_EQ(::mkfifo(path("pipe.exr").c_str(), 0600), 0);
  fs::create_symlink("/dev/null", path("null.png"));
  fs::create_symlink("/proc/self/fd/1", path("stdout.png"));
  std::ofstream(path("none.shard.exr")) << "";  // an existing part: the output is checked first
  struct Case {
    std::string arguments, option, target, kind;
  };
  const std::string render = "render -q --width 16 --height 12 --spp 1 ";
  for (const Case& c : std::vector<Case>{
           {render + "-o " + path("pipe.png"), "--output", path("pipe.png"), "a FIFO"},
           {render + "-o " + path("null.png"), "--output", path("null.png"), "character device"},
           {render + "-o " + path("stdout.png"), "--output", path("stdout.png"), "symbolic link"},
           {render + "-o " + path("ok.png") + " --ground-truth " + path("pipe.exr"),
            "--ground-truth", path("pipe.exr"), "a FIFO"},
           {"merge " + path("none.shard.exr") + " -o " + path("pipe.png"), "--output",
            path("pipe.png"), "a FIFO"},
       }) {
    SCOPED_TRACE(c.arguments);
    auto result = test::run_cli(c.arguments);
    EXPECT_EQ(result.exit_code, 2) << result.output;
    EXPECT_NE(result.output.find(c.option + " " + c.target + ": "), std::string::npos)
        << result.output;
    EXPECT_NE(result.output.find(c.kind), std::string::npos) << result.output;
  }
  EXPECT_TRUE(fs::is_fifo(path("pipe.png")));
  EXPECT_TRUE(fs::is_fifo(path("pipe.exr")));
  EXPECT_TRUE(fs::is_symlink(path("null.png")));
  EXPECT_TRUE(fs::is_character_file("/dev/null"));
  EXPECT_FALSE(fs::exists(path("ok.png")));  // refused before rendering
}

TEST_F(OutputTargetsCli, ConvertAndDiffOutputsAreCheckedToo) {
  ASSERT_EQ(::mkfifo(path("pipe.png").c_str(), 0600), 0);
  ASSERT_EQ(test::run_cli("render -q --width 16 --height 12 --spp 1 -o " + path("a.exr")).exit_code,
            0);
  auto convert = test::run_cli("image convert " + path("a.exr") + " " + path("pipe.png"));
  EXPECT_EQ(convert.exit_code, 2) << convert.output;
  EXPECT_NE(convert.output.find("a FIFO"), std::string::npos) << convert.output;
  auto diff = test::run_cli("image diff " + path("a.exr") + " " + path("a.exr") + " --heatmap " +
                            path("pipe.png"));
  EXPECT_EQ(diff.exit_code, 2) << diff.output;
  EXPECT_NE(diff.output.find("--heatmap " + path("pipe.png")), std::string::npos) << diff.output;
  EXPECT_TRUE(fs::is_fifo(path("pipe.png")));
}

// Under a file-size limit (failing like a full disk; 20 or 40 KiB: the frame is ~11 KB, its
// ground truth ~80 KB) the ground truth cannot be written: the
// previous frame is kept as it was, not replaced by a frame without its ground truth.
TEST_F(OutputTargetsCli, FrameAndGroundTruthAreReplacedTogetherOrNotAtAll) {
  { std::ofstream(path("frame.png")) << "previous frame"; }
  std::string command =
      "ulimit -f 40; " + test::cli_command_line(
                             "render motion-blur -q --width 96 --height 72 "
                             "--spp 1 -o " +
                             path("frame.png") + " --ground-truth " + path("truth.exr"));
  auto result = test::run_shell(command);
  EXPECT_EQ(result.exit_code, 1) << result.output;
  EXPECT_NE(result.output.find(path("truth.exr")), std::string::npos) << result.output;
  EXPECT_EQ(test::read_file(path("frame.png")), "previous frame");
  EXPECT_FALSE(fs::exists(path("truth.exr")));
  for (const auto& entry : fs::directory_iterator(dir_))
    EXPECT_EQ(entry.path().filename().string().find("tmp"), std::string::npos) << entry.path();
  // Without the limit both are written.
  auto written = test::run_cli("render motion-blur -q --width 96 --height 72 --spp 1 -o " +
                               path("frame.png") + " --ground-truth " + path("truth.exr"));
  ASSERT_EQ(written.exit_code, 0) << written.output;
  EXPECT_NE(test::read_file(path("frame.png")), "previous frame");
  EXPECT_TRUE(fs::exists(path("truth.exr")));
}

}  // namespace
}  // namespace obscura
