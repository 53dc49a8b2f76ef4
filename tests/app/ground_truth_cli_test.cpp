// `obscura render --ground-truth FILE.exr [--flow-times A:B]` with both renderers, --crop, and
// the refusals of bad paths and options (exit status 2 for usage, nothing written).
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <vector>

#include "obscura/io/image_io.h"
#include "run_command.h"

namespace obscura {
namespace {

class GroundTruthCli : public test::TempDirTest {};

std::vector<double> numbers(const std::string& text) {
  std::istringstream in(text);
  std::vector<double> v;
  for (double x; in >> x;) v.push_back(x);
  return v;
}

float channel(const Image& image, const std::string& name, int x, int y) {
  for (int c = 0; c < image.channels; ++c)
    if (image.channel_names[c] == name) return image.at(x, y, c);
  ADD_FAILURE() << "no channel " << name;
  return 0;
}

// The motion-blur scene: a 35 mm lens on a 36 mm sensor; fx = 35 · 64 / 36 px.
TEST_F(GroundTruthCli, BothRenderersWriteTheChannelsAndTheCamera) {
  for (const std::string renderer : {"path", "raster"}) {
    SCOPED_TRACE(renderer);
    const std::string gt = path("gt_" + renderer + ".exr");
    auto result = test::run_cli("render motion-blur -q --width 64 --height 48 --spp 1 --renderer " +
                                renderer + " -o " + path(renderer + ".png") + " --ground-truth " +
                                gt + " --focal-length 35 --sensor 36x24");
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_NE(result.output.find(gt), std::string::npos);  // listed with the outputs
    ImageMetadata metadata;
    const Image image = read_exr_data(gt, metadata);
    EXPECT_EQ(image.width, 64);
    EXPECT_EQ(image.height, 48);
    EXPECT_EQ(image.channels, 18);
    std::string k;
    for (const auto& [key, value] : metadata.attributes)
      if (key == "obscura:camera:K") k = value;
    const std::vector<double> K = numbers(k);
    ASSERT_EQ(K.size(), 4u);
    EXPECT_NEAR(K[0], 35.0 * 64 / 36, 1e-9);
    EXPECT_NEAR(K[2], 31.5, 1e-9);
    EXPECT_NEAR(K[3], 23.5, 1e-9);
    int seen = 0;
    for (int y = 0; y < 48; ++y)
      for (int x = 0; x < 64; ++x) seen += channel(image, "instance", x, y) >= 0;
    EXPECT_GT(seen, 64 * 48 / 10);
  }
}

TEST_F(GroundTruthCli, CropGivesTheCropWindowsPixels) {
  const std::string gt = path("crop.exr");
  auto result =
      test::run_cli("render motion-blur -q --width 64 --height 48 --spp 1 -o " + path("crop.png") +
                    " --crop 0.25,0.5,0.75,1 --ground-truth " + gt + " --flow-times 0:1/60");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  ImageMetadata metadata;
  const Image image = read_exr_data(gt, metadata);
  EXPECT_EQ(image.width, 32);
  EXPECT_EQ(image.height, 24);
  for (const auto& [key, value] : metadata.attributes) {
    if (key == "obscura:camera:crop") {
      EXPECT_EQ(value, "16 24 48 48");
    }
    if (key == "obscura:ground_truth:times") {
      EXPECT_EQ(numbers(value)[1], 1.0 / 60);
    }
  }
  EXPECT_EQ(channel(image, "time", 0, 0), 0.f);
}

TEST_F(GroundTruthCli, BadPathsAndOptionsAreRefused) {
  const std::string base =
      "render motion-blur -q --width 16 --height 16 --spp 1 -o " + path("image.exr") + " ";
  test::expect_refusals(
      base, {{"--ground-truth " + path("gt.png"), "must end in .exr"},
             {"--ground-truth " + path("missing/gt.exr"), "missing"},
             {"--ground-truth " + path("image.exr"), "the image's own output"},
             {"--ground-truth " + path("gt.exr") + " --flow-times 0", "--flow-times expects A:B"},
             {"--ground-truth " + path("gt.exr") + " --flow-times 0:x", "expects a number"},
             {"--flow-times 0:1", "give --ground-truth"},
             {"--ground-truth " + path("gt.exr") + " --shard 0/2", "--shard"},
             {"--ground-truth " + path("gt.exr") + " --frames 0:1", "--frames"}});
  EXPECT_FALSE(std::filesystem::exists(path("gt.exr")));
  EXPECT_FALSE(std::filesystem::exists(path("gt.png")));
  auto usage = test::run_cli(base + "--ground-truth " + path("gt.png"));
  EXPECT_EQ(usage.exit_code, 2) << usage.output;
}

}  // namespace
}  // namespace obscura
