// `obscura render --frames A:B[:STEP] --fps F`: frame n of a sequence is the image `--time n/F`
// renders alone, bit for bit, whether the sequence runs in one process or on several MPI ranks;
// numbered files resume (finished frames are skipped, partial or unreadable ones rendered again);
// a .y4m video holds the same frames developed. The reference is always the frame rendered on its
// own.
#include <gtest/gtest.h>

#include <OpenImageIO/imagebuf.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "app/image_files.h"
#include "app/mpi_launcher.h"
#include "run_command.h"
#include "test_paths.h"

namespace obscura {
namespace {

namespace fs = std::filesystem;
using test::file_text;
using test::files_in;
using test::same_pixels;

// The ball and the box of motion-blur.json move during its first 1/30 s only (its motion keys
// end there; later times hold the last pose). At 100 frames per second frames 0 … 5 are exposed
// around 0 … 50 ms: each catches the scene at another pose, so that no two are alike. (At 10 fps
// every frame after the first would show the same final pose.)
constexpr int kFps = 100;
const int kFrames[] = {0, 1, 2, 3, 4, 5};

std::string scene_arguments() {
  return test::quoted(test::source_path("scenes/motion-blur.json")) +
         " --width 64 --height 36 --spp 4";
}

std::string sequence_arguments() {
  return "render " + scene_arguments() + " --frames 0:5 --fps " + std::to_string(kFps);
}

// Frame n's time, n / fps, written so that it reads back as the same double.
std::string time_of_frame(int n) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", double(n) / kFps);
  return text;
}

std::string frame_name(const std::string& stem, int n) {
  char name[64];
  std::snprintf(name, sizeof name, "%s_%04d.exr", stem.c_str(), n);
  return name;
}

// The frames of a YUV4MPEG2 stream of 4:2:0 frames, each as its bytes; fails the test on a
// stream that is not whole frames.
std::vector<std::string> y4m_frames(const std::string& path) {
  const std::string bytes = file_text(path);
  const size_t header_end = bytes.find('\n');
  int width = 0, height = 0;
  std::sscanf(bytes.c_str(), "YUV4MPEG2 W%d H%d", &width, &height);
  EXPECT_GT(width, 0) << path;
  EXPECT_NE(bytes.substr(0, header_end).find(" C420"), std::string::npos) << path;
  const size_t frame_size =
      size_t(width) * height + 2 * size_t((width + 1) / 2) * size_t((height + 1) / 2);
  std::vector<std::string> frames;
  for (size_t at = header_end + 1; at < bytes.size();) {
    if (bytes.compare(at, 5, "FRAME") != 0) {
      ADD_FAILURE() << path << ": no FRAME at byte " << at;
      break;
    }
    const size_t data = bytes.find('\n', at) + 1;
    if (data == 0 || data + frame_size > bytes.size()) {
      ADD_FAILURE() << path << ": a frame is cut short at byte " << at;
      break;
    }
    frames.push_back(bytes.substr(data, frame_size));
    at = data + frame_size;
  }
  return frames;
}

// Frame n rendered on its own, as `--time n/fps`, to alone_N.EXTENSION.
std::string alone_arguments(int n, const std::string& alone_path) {
  return "render " + scene_arguments() + " --time " + time_of_frame(n) + " -q -o " + alone_path;
}

class SequenceCli : public test::TempDirTest {
 protected:
  std::string alone_file(int n, const std::string& extension) {
    return path("alone_" + std::to_string(n) + extension);
  }
  // The sequence `arguments`, and every frame on its own, all at once (independent renders that
  // mostly wait for the CLI to start).
  void render_sequence_and_frames_alone(const std::string& arguments,
                                        const std::string& extension) {
    std::vector<std::string> commands = {test::cli_command_line(arguments)};
    for (int n : kFrames)
      commands.push_back(test::cli_command_line(alone_arguments(n, alone_file(n, extension))));
    for (const test::CommandResult& r : test::run_shells_concurrently(commands))
      ASSERT_EQ(r.exit_code, 0) << r.output;
  }
};

TEST_F(SequenceCli, EachFrameIsItsTimeRenderedAlone) {
  render_sequence_and_frames_alone(sequence_arguments() + " -q -o " + path("f_%04d.exr"), ".exr");
  for (int n : kFrames) {
    EXPECT_TRUE(fs::exists(path(frame_name("f", n)))) << frame_name("f", n);
    EXPECT_TRUE(same_pixels(path(frame_name("f", n)), alone_file(n, ".exr")));
  }
  EXPECT_EQ(files_in(dir_).size(), 12u) << "six frames and six renders alone";
  // The scene moves: no two frames are the same image.
  for (int a : kFrames)
    for (int b = a + 1; b <= kFrames[5]; ++b)
      EXPECT_FALSE(same_pixels(path(frame_name("f", a)), path(frame_name("f", b))))
          << "frames " << a << " and " << b;
}

TEST_F(SequenceCli, AVideoHoldsTheFramesDevelopedAsEachAloneWouldBe) {
  render_sequence_and_frames_alone(sequence_arguments() + " -q -o " + path("video.y4m"), ".y4m");
  const std::vector<std::string> frames = y4m_frames(path("video.y4m"));
  ASSERT_EQ(frames.size(), 6u);
  EXPECT_NE(file_text(path("video.y4m")).find(" F100:1 "), std::string::npos);
  for (int n : kFrames) {
    const std::vector<std::string> alone = y4m_frames(alone_file(n, ".y4m"));
    ASSERT_EQ(alone.size(), 1u);
    EXPECT_TRUE(frames[size_t(n)] == alone[0]) << "frame " << n;
  }
}

TEST_F(SequenceCli, ARunAgainRendersOnlyTheFramesThatAreNotFinished) {
  const std::string pattern = path("f_%04d.exr");
  auto r = test::run_cli(sequence_arguments() + " -q -o " + pattern);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  // Copies of the first run's frames: what every frame rendered again must be.
  fs::create_directory(path("first"));
  for (int n : kFrames)
    fs::copy_file(path(frame_name("f", n)), path("first/" + frame_name("f", n)));
  auto modified = [&] {
    std::map<int, fs::file_time_type> times;
    for (int n : kFrames)
      if (fs::exists(path(frame_name("f", n))))
        times[n] = fs::last_write_time(path(frame_name("f", n)));
    return times;
  };
  auto expect_rendered_again = [&](const std::vector<int>& again) {
    std::map<int, fs::file_time_type> before = modified();
    auto result = test::run_cli(sequence_arguments() + " -o " + pattern);
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_NE(result.output.find("sequence: 6 frames, 2 rendered here, 4 already there"),
              std::string::npos)
        << result.output;
    std::map<int, fs::file_time_type> after = modified();
    for (int n : kFrames) {
      const std::string frame = path(frame_name("f", n));
      EXPECT_TRUE(same_pixels(frame, path("first/" + frame_name("f", n))));
      EXPECT_EQ(test::image_attribute(frame, "obscura:partial"), "") << frame;
      const bool rendered = std::find(again.begin(), again.end(), n) != again.end();
      if (!rendered) {
        EXPECT_EQ(after[n], before[n]) << frame << " was written again";
      }
    }
  };

  // Two frames missing.
  fs::remove(path(frame_name("f", 2)));
  fs::remove(path(frame_name("f", 4)));
  expect_rendered_again({2, 4});

  // A frame marked partial (a render stopped early) and one that is not an image.
  OIIO::ImageBuf partial(path(frame_name("f", 3)));
  ASSERT_TRUE(partial.read(0, 0, true, OIIO::TypeDesc::FLOAT)) << partial.geterror();
  partial.specmod().attribute("obscura:partial", "interrupted");
  ASSERT_TRUE(partial.write(path(frame_name("f", 3)))) << partial.geterror();
  ASSERT_EQ(test::image_attribute(path(frame_name("f", 3)), "obscura:partial"), "interrupted");
  std::ofstream(path(frame_name("f", 1)), std::ios::binary | std::ios::trunc) << "garbage";
  expect_rendered_again({1, 3});

  // Frames cut short after their header (a copy or a disk that filled outside Obscura): the
  // header alone reads fine, the pixels do not.
  for (int n : {0, 5}) {
    const std::string frame = path(frame_name("f", n));
    fs::resize_file(frame, fs::file_size(frame) / 2);
  }
  expect_rendered_again({0, 5});
}

// A pattern wider than any fixed buffer names every frame apart, and a run again finds them all.
TEST_F(SequenceCli, FramePatternsOfAnyWidth) {
  const std::string arguments =
      "render --width 8 --height 6 --spp 1 --frames 0:2 -o " + path("w_%040d.exr");
  auto first = test::run_cli(arguments);
  ASSERT_EQ(first.exit_code, 0) << first.output;
  for (int n : {0, 1, 2})
    EXPECT_TRUE(fs::exists(path("w_" + std::string(39, '0') + std::to_string(n) + ".exr")));
  EXPECT_EQ(files_in(dir_).size(), 3u);
  fs::remove(path("w_" + std::string(39, '0') + "2.exr"));
  auto again = test::run_cli(arguments);
  ASSERT_EQ(again.exit_code, 0) << again.output;
  EXPECT_NE(again.output.find("sequence: 3 frames, 1 rendered here, 2 already there"),
            std::string::npos)
      << again.output;
}

// 200 M frame numbers are counted, not listed (a list would be 800 MB to 1.5 GB while it grows):
// under a 1.2 GB address space the first frames are written at once, and SIGTERM stops the run.
TEST_F(SequenceCli, AHugeFrameRangeStartsAtOnceInBoundedMemory) {
  const std::string command = test::address_space_limit(1'200'000) +
                              test::cli_command_line(
                                  "render --width 8 --height 6 --spp 1 --frames "
                                  "-100000000:100000000 -o " +
                                  path("h_%d.exr")) +
                              " & sleep 3; kill -TERM $!; wait $!";
  auto result = test::run_shell(command);
  EXPECT_EQ(result.exit_code, 143) << result.output;  // 128 + SIGTERM
  EXPECT_TRUE(fs::exists(path("h_-100000000.exr"))) << result.output;
  EXPECT_NE(result.output.find("sequence: 200000001 frames"), std::string::npos) << result.output;
}

TEST_F(SequenceCli, OptionsThatDoNotMakeASequenceAreRefused) {
  const std::string frames = " --frames 0:5 -o " + path("f_%04d.exr");
  const std::vector<test::Refusal> refusals = {
      {" --frames 5:1 -o " + path("f_%04d.exr"), "LAST is before FIRST"},
      {" --frames a:b -o " + path("f_%04d.exr"), "'a:b'"},
      {" --frames 0:4:0 -o " + path("f_%04d.exr"), "STEP must be at least 1"},
      {" --frames 0:5 -o " + path("f.exr"), "one integer conversion"},
      {" --frames 0:5 -o " + path("f_%d_%04d.exr"), "one integer conversion"},
      {" --fps 10 -o " + path("f.exr"), "--frames"},
      {frames + " --time 0.1", "--time and --frames"},
      {frames + " --shard 0/2", "--shard splits one frame"},
  };
  test::expect_refusals("render " + scene_arguments(), refusals);
  EXPECT_TRUE(files_in(dir_).empty());
}

class SequenceOnRanks : public test::MpiCliTest {};

TEST_F(SequenceOnRanks, TwoRanksWriteTheSameFramesAndTheSameVideo) {
  const std::vector<test::CommandResult> results = test::run_shells_concurrently({
      test::cli_command_line(sequence_arguments() + " -q -o " + path("one_%04d.exr")),
      mpirun_obscura(2, sequence_arguments() + " -o " + path("two_%04d.exr")),
      test::cli_command_line(sequence_arguments() + " -q -o " + path("one.y4m")),
      mpirun_obscura(2, sequence_arguments() + " -q -o " + path("two.y4m")),
  });
  for (const test::CommandResult& r : results) ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(results[1].output.find("sequence: 6 frames, "), std::string::npos) << results[1].output;
  for (int n : kFrames)
    EXPECT_TRUE(same_pixels(path(frame_name("two", n)), path(frame_name("one", n))));
  EXPECT_EQ(y4m_frames(path("two.y4m")).size(), 6u);
  EXPECT_TRUE(file_text(path("two.y4m")) == file_text(path("one.y4m")))
      << "the 2-rank video differs from the 1-rank one";
}

}  // namespace
}  // namespace obscura
