// The tracer's options of `obscura render`, run as a user would.
#include <gtest/gtest.h>

#include <filesystem>

#include "obscura/io/image_io.h"
#include "run_command.h"

namespace obscura {
namespace {

namespace fs = std::filesystem;

class TracerCli : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = test::make_temp_dir("obscura-tracer-cli"); }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (fs::path(dir_) / name).string(); }
  std::string dir_;
};

TEST_F(TracerCli, EveryRendererRenders) {
  for (const char* renderer : {"path", "whitted", "direct"}) {
    auto r = test::run_cli(std::string("render --renderer ") + renderer +
                           " --width 24 --height 24 --spp 2 -o " + path("r.exr"));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find(std::string("(") + renderer + ")"), std::string::npos) << r.output;
  }
}

TEST_F(TracerCli, UnknownRendererOrSamplerIsAUsageError) {
  auto r = test::run_cli("render --renderer photon -o " + path("r.png"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("--renderer must be path, whitted, direct, raster or reyes; got 'photon'"),
            std::string::npos)
      << r.output;
  r = test::run_cli("render --sampler halton -o " + path("r.png"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("--sampler"), std::string::npos) << r.output;
  r = test::run_cli("render --max-depth 0 -o " + path("r.png"));
  EXPECT_EQ(r.exit_code, 2);
}

TEST_F(TracerCli, AovsAreWrittenBesideTheImage) {
  auto r = test::run_cli("render --width 16 --height 16 --spp 1 --aovs -o " + path("a.png"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const char* name : {"albedo", "normal", "depth", "range", "id"}) {
    std::string file = path(std::string("a.") + name + ".exr");
    EXPECT_TRUE(fs::exists(file)) << file;
    EXPECT_NE(r.output.find(file), std::string::npos);
  }
  Image depth = read_image(path("a.depth.exr"));
  EXPECT_EQ(depth.channels, 1);
  EXPECT_GT(depth.at(8, 8, 0), 0.5f);  // the back wall is about a metre and a half away
}

TEST_F(TracerCli, SamplersAreDeterministicAtAnyThreadCount) {
  for (const char* sampler : {"sobol", "independent"}) {
    auto one = test::run_cli(std::string("render -q --sampler ") + sampler +
                             " --width 20 --height 20 --spp 4 --threads 1 -o " + path("1.exr"));
    auto two = test::run_cli(std::string("render -q --sampler ") + sampler +
                             " --width 20 --height 20 --spp 4 --threads 2 -o " + path("2.exr"));
    ASSERT_EQ(one.exit_code, 0) << one.output;
    ASSERT_EQ(two.exit_code, 0) << two.output;
    EXPECT_EQ(read_image(path("1.exr")).data, read_image(path("2.exr")).data) << sampler;
  }
}

}  // namespace
}  // namespace obscura
