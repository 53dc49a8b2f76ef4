// `obscura render --renderer raster` with the camera effects: --raster-dof and
// --raster-samples, and motion blur whenever the shutter is open and something moves.
#include <gtest/gtest.h>

#include <filesystem>

#include "obscura/io/image_io.h"
#include "run_command.h"

namespace obscura {
namespace {

namespace fs = std::filesystem;

class RasterEffectsCli : public test::TempDirTest {
 protected:
  // Renders at 64 × 36 unless the arguments give a size.
  Image render(const std::string& arguments, const std::string& name) {
    std::string size =
        arguments.find("--width") == std::string::npos ? "--width 64 --height 36 " : "";
    auto r = test::run_cli("render -q --renderer raster " + size + arguments + " -o " + path(name));
    EXPECT_EQ(r.exit_code, 0) << arguments << ": " << r.output;
    return read_image(path(name));
  }
};

// Mean absolute difference per channel value.
double difference(const Image& a, const Image& b) {
  double sum = 0;
  for (size_t i = 0; i < a.data.size(); ++i) sum += std::abs(a.data[i] - b.data[i]);
  return sum / double(a.data.size());
}

TEST_F(RasterEffectsCli, DepthOfFieldByAccumulationAndPostProcessBlurTheScene) {
  // At 320 pixels across, f/1.8 blurs the horizon and the farthest boxes by a few pixels; at
  // f/16 the same scene stays nearly sharp.
  const std::string scene = "depth-of-field --width 320 --height 180 ";
  for (const char* method : {"accumulate --raster-samples 16", "post"}) {
    const std::string dof = std::string(" --raster-dof ") + method;
    double wide = difference(render(scene + dof, "wide.exr"),
                             render(scene + "--raster-dof off", "wide-sharp.exr"));
    double narrow = difference(render(scene + "--camera f16" + dof, "narrow.exr"),
                               render(scene + "--camera f16 --raster-dof off", "narrow-sharp.exr"));
    EXPECT_GT(wide, 2e-4) << method;
    EXPECT_GT(wide, 3 * narrow) << method;
  }
}

TEST_F(RasterEffectsCli, AccumulationIsBitIdenticalForAnyThreadCount) {
  Image one = render("motion-blur --raster-samples 6 --threads 1", "one.exr");
  Image two = render("motion-blur --raster-samples 6 --threads 2", "two.exr");
  EXPECT_EQ(one.data, two.data);
}

TEST_F(RasterEffectsCli, MotionBlursWhileTheShutterIsOpen) {
  Image blurred = render("motion-blur --raster-samples 8", "blurred.exr");
  Image instant = render("motion-blur --raster-samples 8 --shutter 0:0", "instant.exr");
  Image single = render("motion-blur --raster-samples 1", "single.exr");
  EXPECT_GT(difference(blurred, instant), 1e-3);
  EXPECT_GT(difference(blurred, single), 1e-3);
}

TEST_F(RasterEffectsCli, BadOptionsAreUsageErrors) {
  struct Case {
    const char* arguments;
    const char* message;
  };
  for (const Case& c : {Case{"--renderer raster --raster-dof blur",
                             "--raster-dof must be off, accumulate or post; got 'blur'"},
                        Case{"--renderer raster --raster-samples 0",
                             "--raster-samples: expected an integer from 1 to 65536; got '0'"},
                        Case{"--renderer path --raster-dof post",
                             "--raster-dof applies to --renderer raster only"}}) {
    auto r = test::run_cli(std::string("render ") + c.arguments + " -o " + path("x.png"));
    EXPECT_EQ(r.exit_code, 2) << c.arguments << ": " << r.output;
    EXPECT_NE(r.output.find(c.message), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(path("x.png")));
  }
}

}  // namespace
}  // namespace obscura
