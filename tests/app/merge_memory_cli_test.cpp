// `obscura merge` holds the frame and one part, never every part: merging the 8 parts of a
// 1024 × 1024 frame peaks (resident set) within the memory of a few frames above what merging
// the 8 parts of a tiny frame takes (the program itself), well below the 8 frames that holding
// every part would need (each part is a whole film, the other parts' pixels zero).
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "run_command.h"

namespace obscura {
namespace {

// The peak resident set of a shell command line, in bytes; -1 when it failed. Measured by a
// small Python parent (the largest resident set of the processes it waited for): a child of this
// test process would count the test's own pages, copied at the fork, in its peak.
long long peak_rss_bytes(const std::string& command_line) {
  const std::string script =
      "import resource, subprocess, sys\n"
      "r = subprocess.run(sys.argv[1], shell=True, stdout=subprocess.DEVNULL, "
      "stderr=subprocess.DEVNULL)\n"
      "print(resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss if r.returncode == 0 "
      "else -1)\n";
  std::string quoted;  // the command line as one single-quoted shell word
  for (char c : command_line) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  const test::CommandResult r = test::run_shell("python3 -c '" + script + "' '" + quoted + "'");
  if (r.exit_code != 0) return -1;
  const long long kib = std::atoll(r.output.c_str());
  return kib > 0 ? kib * 1024 : -1;  // ru_maxrss is in KiB on Linux
}

class MergeMemoryCli : public test::TempDirTest {
 protected:
  // Renders the 8 parts of a `size` frame (the rasterizer, side by side); their file names.
  std::vector<std::string> parts(const std::string& name, const std::string& size) {
    std::vector<std::string> commands, files;
    for (int i = 0; i < 8; ++i) {
      files.push_back(path(name + std::to_string(i) + ".exr"));
      commands.push_back(test::cli_command_line("render --renderer raster " + size +
                                                " -q --shard " + std::to_string(i) + "/8 -o " +
                                                files.back()));
    }
    for (const test::CommandResult& r : test::run_shells_concurrently(commands))
      EXPECT_EQ(r.exit_code, 0) << r.output;
    return files;
  }
  std::string merge_command(const std::vector<std::string>& files, const std::string& output) {
    std::string arguments = "merge -q -o " + output;
    for (const std::string& file : files) arguments += " " + file;
    return test::cli_command_line(arguments);
  }
};

TEST_F(MergeMemoryCli, HoldsTheFrameAndOnePartNotEveryPart) {
  if (test::kAddressSanitizer)
    GTEST_SKIP() << "AddressSanitizer's shadow memory and quarantine hide what merge holds";
  const long long tiny =
      peak_rss_bytes(merge_command(parts("tiny", "--width 16 --height 16"), path("tiny.png")));
  const long long large = peak_rss_bytes(
      merge_command(parts("large", "--width 1024 --height 1024"), path("large.png")));
  ASSERT_GT(tiny, 0);
  ASSERT_GT(large, 0);
  // A part's film: R, G, B and the weight, 4 floats a pixel.
  constexpr long long kFrameBytes = 1024LL * 1024 * 4 * sizeof(float);
  std::printf(
      "merge peak: %.1f MB for 8 parts of 1024 x 1024, %.1f MB for 16 x 16; a frame is "
      "%.1f MB\n",
      large * 1e-6, tiny * 1e-6, kFrameBytes * 1e-6);
  // The frame, the part being added, the finished image and the encoder's rows: about 4 frames.
  // Every part at once would be at least 8.
  EXPECT_LT(large - tiny, 6 * kFrameBytes)
      << "merge peaked at " << large << " bytes, " << tiny << " for a tiny frame";
}

}  // namespace
}  // namespace obscura
