// Numeric options of the command line out of range, malformed or absurd: each is a usage error
// (exit 2) that names the option, the value given and the range allowed, before any work starts.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "run_command.h"
#include "test_paths.h"

namespace obscura {
namespace {

class OptionRangesCli : public test::TempDirTest {
 protected:
  // Runs `obscura <command> <option>` and expects a usage error whose message contains every
  // one of `expected`.
  void expect_usage_error(const std::string& command, const std::string& option,
                          std::initializer_list<std::string> expected) {
    auto r = test::run_cli(command + " " + option + " -o " + path("out.png"));
    EXPECT_EQ(r.exit_code, 2) << option << "\n" << r.output;
    for (const std::string& text : expected)
      EXPECT_NE(r.output.find(text), std::string::npos) << option << ": no '" << text << "' in\n"
                                                        << r.output;
    EXPECT_EQ(r.output.find("internal error"), std::string::npos) << r.output;
    EXPECT_FALSE(std::filesystem::exists(path("out.png"))) << option;
  }
};

TEST_F(OptionRangesCli, ImageSizeIsBoundedPerSideAndInAll) {
  expect_usage_error("render", "--width 200000", {"--width", "200000", "1 to 65536"});
  expect_usage_error("render", "--height 0", {"--height", "'0'", "1 to 65536"});
  expect_usage_error("render", "--width -5", {"--width", "-5"});
  expect_usage_error("render", "--width 5x", {"--width", "'5x'"});
  expect_usage_error("render", "--width 1e3", {"--width", "'1e3'"});
  expect_usage_error("render", "--width 99999999999999999999", {"--width"});
  // Each side within range, the product (2^32) far above 2^28 pixels.
  expect_usage_error("render", "--width 65536 --height 65536", {"65536 x 65536", "268435456"});
  expect_usage_error("camera", "--width 70000", {"--width", "70000", "1 to 65536"});
}

TEST_F(OptionRangesCli, SampleCountsAndDepthsAreBounded) {
  expect_usage_error("render", "--spp 0", {"--spp", "'0'"});
  expect_usage_error("render", "--spp 2e9", {"--spp", "'2e9'", "1 to 1048576"});
  expect_usage_error("render", "--renderer raster --raster-samples 2e9",
                     {"--raster-samples", "'2e9'", "1 to 65536"});
  expect_usage_error("render", "--renderer raster --raster-samples 70000",
                     {"--raster-samples", "70000"});
  expect_usage_error("render", "--renderer whitted --max-depth 10000",
                     {"--max-depth", "10000", "1 to 1024"});
  expect_usage_error("render", "--max-depth nan", {"--max-depth", "'nan'"});
  expect_usage_error("render", "--renderer raster --msaa 99", {"--msaa", "99"});
  expect_usage_error("render", "--renderer raster --shadow-map 1e9", {"--shadow-map", "'1e9'"});
}

TEST_F(OptionRangesCli, SeedMustBeANonNegative64BitInteger) {
  expect_usage_error("render", "--seed -1", {"--seed", "'-1'", "0 to 18446744073709551615"});
  expect_usage_error("render", "--seed 18446744073709551616", {"--seed", "18446744073709551616"});
  expect_usage_error("render", "--seed 3.5", {"--seed", "'3.5'"});
}

TEST_F(OptionRangesCli, ThreadsAndTimeLimitAreBounded) {
  expect_usage_error("render", "--threads -2", {"--threads", "'-2'", "0 to 4096"});
  expect_usage_error("render", "--threads 1000000", {"--threads", "1000000"});
  expect_usage_error("render", "--time-limit inf", {"--time-limit", "'inf'"});
  expect_usage_error("render", "--time-limit -1", {"--time-limit", "'-1'"});
  expect_usage_error("render", "--time-limit 1e300", {"--time-limit", "1e300"});
}

TEST_F(OptionRangesCli, ExposureAndFilterRadiusCannotOverflowTheImage) {
  // 1e308 EV would scale every pixel by 2^1e308 = inf; NaN, inf and garbage are not numbers.
  expect_usage_error("render", "--exposure 1e308", {"--exposure", "1e308", "-64 to 64"});
  expect_usage_error("render", "--exposure nan", {"--exposure", "'nan'"});
  expect_usage_error("render", "--exposure 2EV", {"--exposure", "'2EV'"});
  expect_usage_error("render", "--filter-radius 1e6", {"--filter-radius", "1e6", "to 16"});
  expect_usage_error("render", "--filter-radius 0", {"--filter-radius", "'0'"});
  expect_usage_error("render", "--environment-intensity inf", {"--environment-intensity"});
  expect_usage_error("render", "--bits 17", {"--bits", "17", "1 to 16"});
  expect_usage_error("render", "--reinhard-white inf", {"--reinhard-white", "'inf'"});
  expect_usage_error("render", "--shutter 0:1e400", {"--shutter", "1e400"});
  expect_usage_error("camera", "--fov inf", {"--fov", "'inf'"});
  expect_usage_error("camera", "--aperture-blades 1e9", {"--aperture-blades", "'1e9'"});
  expect_usage_error("camera", "--iso -100", {"--iso", "'-100'"});
  auto r = test::run_cli("image convert in.exr " + path("o.png") + " --exposure 1e308");
  EXPECT_EQ(r.exit_code, 2) << r.output;
}

TEST_F(OptionRangesCli, ValuesAtTheLimitsAreAccepted) {
  auto r = test::run_cli("camera --width 65536 --height 4096 --exposure -64 --filter-radius 16");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  r = test::run_cli(
      "render -q --width 8 --height 8 --spp 1 --seed 18446744073709551615 "
      "--renderer whitted --max-depth 1024 --threads 1 -o " +
      path("ok.exr"));
  EXPECT_EQ(r.exit_code, 0) << r.output;
}

TEST_F(OptionRangesCli, RunningOutOfMemoryIsReportedNotAnInternalError) {
  // A 2^28-pixel film is within the limits, but not within 1.5 GB of address space: the
  // allocation fails, and that must read as what it is, with exit 1 and no output file.
  if (test::kAddressSanitizer) GTEST_SKIP() << "ulimit -v cannot run under AddressSanitizer";
  // Quoted for the shell (built in place: GCC 12 -O3 sees a false -Wrestrict in "'" + s + "'").
  std::string cli = test::cli_path();
  cli.insert(cli.begin(), '\'');
  cli.push_back('\'');
  auto r = test::run_cli("--version >/dev/null; ulimit -v 1500000; " + cli +
                         " render -q --width 16384 --height 16384 --spp 1 -o " + path("big.exr"));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("obscura: out of memory while running 'obscura render'"),
            std::string::npos)
      << r.output;
  EXPECT_EQ(r.output.find("internal error"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(path("big.exr")));
}

}  // namespace
}  // namespace obscura
