// Renders that end early — Ctrl-C, or a time limit reached before the samples asked for — in both
// renderers: the image so far is written, marked partial in the file, and the exit status says
// how the render ended (0 complete, 3 time limit, 130 interrupted by SIGINT, 143 by SIGTERM).
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "obscura/io/image_io.h"
#include "run_command.h"

namespace obscura {
namespace {

namespace fs = std::filesystem;

// The file's "obscura:partial" and "ImageDescription" attributes, read by OpenImageIO itself.
struct FileMarks {
  std::string partial, description;
};

FileMarks marks_of(const std::string& path) {
  auto in = OIIO::ImageInput::open(path);
  EXPECT_TRUE(in) << path << ": " << OIIO::geterror();
  if (!in) return {};
  return {in->spec().get_string_attribute("obscura:partial"),
          in->spec().get_string_attribute("ImageDescription")};
}

std::string first_line(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  std::getline(in, line);
  return line;
}

class PartialRenderCli : public test::TempDirTest {};

// Ctrl-C after `seconds` of a command started in the background (where a non-interactive shell
// starts it with SIGINT ignored: the renderer must still stop).
std::string interrupted_after(const std::string& arguments, double seconds,
                              const std::string& signal = "INT") {
  return arguments + " 2>&1 & sleep " + std::to_string(seconds) + "; kill -" + signal +
         " $!; wait $!";
}

TEST_F(PartialRenderCli, TracerTimeLimitWithoutSppIsComplete) {
  // Without --spp a time limit asks for as many samples as fit: reaching it completes the render.
  auto r = test::run_cli("render --width 32 --height 32 --time-limit 0.5 -o " + path("t.exr"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("[time limit reached]"), std::string::npos) << r.output;
  EXPECT_EQ(marks_of(path("t.exr")).partial, "");
  EXPECT_GT(read_image(path("t.exr")).rgb(16, 16).g, 0.f);
}

TEST_F(PartialRenderCli, TracerTimeLimitBeforeTheSamplesAskedForIsPartial) {
  for (const char* ext : {"exr", "png"}) {
    std::string out = path(std::string("t.") + ext);
    auto r = test::run_cli("render --width 48 --height 48 --spp 1000000 --time-limit 0.5 -o " +
                           out + " --aovs");
    ASSERT_EQ(r.exit_code, 3) << r.output;
    EXPECT_NE(r.output.find("[partial: time limit, "), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(" of 1000000 samples per pixel]"), std::string::npos) << r.output;
    FileMarks marks = marks_of(out);
    EXPECT_EQ(marks.partial, "time limit");
    EXPECT_NE(marks.description.find("of 1000000 samples per pixel"), std::string::npos)
        << marks.description;
    EXPECT_GT(read_image(out).rgb(24, 24).g, 0.f);
    // The AOVs hold the same partial passes and say so too.
    EXPECT_EQ(marks_of(path("t.depth.exr")).partial, "time limit");
  }
}

TEST_F(PartialRenderCli, TracerInterruptWritesTheImageMarkedInterrupted) {
  auto r = test::run_cli(
      interrupted_after("render --width 64 --height 64 --spp 100000 -o " + path("i.exr"), 2));
  ASSERT_EQ(r.exit_code, 130) << r.output;
  EXPECT_NE(r.output.find("[partial: interrupted, "), std::string::npos) << r.output;
  EXPECT_EQ(marks_of(path("i.exr")).partial, "interrupted");
  EXPECT_GT(read_image(path("i.exr")).rgb(32, 32).g, 0.f);
}

// SIGTERM (a farm manager's cancel) stops the render the same way; the exit status says which
// signal it was: 128 + 15, as a shell reports a command SIGTERM ended.
TEST_F(PartialRenderCli, TracerSigtermWritesTheImageMarkedInterruptedAndExits143) {
  auto r = test::run_cli(interrupted_after(
      "render --width 64 --height 64 --spp 100000 -o " + path("t.exr"), 2, "TERM"));
  ASSERT_EQ(r.exit_code, 143) << r.output;
  EXPECT_NE(r.output.find("[partial: interrupted, "), std::string::npos) << r.output;
  EXPECT_EQ(marks_of(path("t.exr")).partial, "interrupted");
  EXPECT_GT(read_image(path("t.exr")).rgb(32, 32).g, 0.f);
}

// The rasterizer accumulates frames for depth of field: 65,536 of them cannot finish in time.
const std::string kManyRasterFrames =
    "render --renderer raster --width 256 --height 256 --fstop 2 --raster-samples 65536";

TEST_F(PartialRenderCli, RasterTimeLimitStopsBetweenFrames) {
  auto r = test::run_cli(kManyRasterFrames + " --time-limit 0.5 --aovs -o " + path("r.png"));
  ASSERT_EQ(r.exit_code, 3) << r.output;
  EXPECT_NE(r.output.find(" of 65536 frames]"), std::string::npos) << r.output;
  FileMarks marks = marks_of(path("r.png"));
  EXPECT_EQ(marks.partial, "time limit");
  EXPECT_NE(marks.description.find("of 65536 frames"), std::string::npos) << marks.description;
  EXPECT_GT(read_image(path("r.png")).rgb(128, 128).g, 0.f);
  EXPECT_EQ(marks_of(path("r.id.exr")).partial, "time limit");
}

TEST_F(PartialRenderCli, RasterInterruptWritesTheFramesSoFar) {
  auto r = test::run_cli(interrupted_after(kManyRasterFrames + " -o " + path("r.exr"), 2));
  ASSERT_EQ(r.exit_code, 130) << r.output;
  EXPECT_NE(r.output.find("[partial: interrupted, "), std::string::npos) << r.output;
  EXPECT_EQ(marks_of(path("r.exr")).partial, "interrupted");
  EXPECT_GT(read_image(path("r.exr")).rgb(128, 128).g, 0.f);
}

TEST_F(PartialRenderCli, RasterSigtermExits143) {
  auto r = test::run_cli(interrupted_after(kManyRasterFrames + " -o " + path("r.exr"), 2, "TERM"));
  ASSERT_EQ(r.exit_code, 143) << r.output;
  EXPECT_EQ(marks_of(path("r.exr")).partial, "interrupted");
}

TEST_F(PartialRenderCli, FormatsWithoutMetadataWarnAndKeepTheExitStatus) {
  auto r = test::run_cli("render --width 32 --height 32 --spp 1000000 --time-limit 0.3 -o " +
                         path("t.pfm"));
  ASSERT_EQ(r.exit_code, 3) << r.output;
  EXPECT_NE(r.output.find("cannot record that the image is partial"), std::string::npos)
      << r.output;
  // Y4M keeps it as a tag of its stream header.
  r = test::run_cli("render --width 32 --height 32 --spp 1000000 --time-limit 0.3 -o " +
                    path("t.y4m"));
  ASSERT_EQ(r.exit_code, 3) << r.output;
  EXPECT_NE(first_line(path("t.y4m")).find(" XOBSCURA_PARTIAL=time_limit"), std::string::npos)
      << first_line(path("t.y4m"));
}

TEST_F(PartialRenderCli, CompleteRendersAreNotMarked) {
  auto r = test::run_cli("render --width 16 --height 16 --spp 2 -o " + path("c.png"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(r.output.find("partial"), std::string::npos) << r.output;
  FileMarks marks = marks_of(path("c.png"));
  EXPECT_EQ(marks.partial, "");
  EXPECT_EQ(marks.description, "");
}

}  // namespace
}  // namespace obscura
