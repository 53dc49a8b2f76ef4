// `render --environment`: a file that brings no light of its own renders lit, not black.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "obscura/io/image_io.h"
#include "run_command.h"
#include "test_paths.h"

namespace obscura {
namespace {

class EnvironmentCli : public test::TempDirTest {
 protected:
  // Box.glb has one red material and no lights; the camera of the automatic framing sees the
  // box in the middle and the environment around it.
  test::CommandResult render(const std::string& renderer, const std::string& environment,
                             const std::string& out) {
    return test::run_cli("render " + test::data_path("gltf/Box/Box.glb") + " --renderer " +
                         renderer + " --width 32 --height 32 --spp 4 --environment " + environment +
                         " -o " + path(out));
  }
};

float mean_luminance(const Image& image) {
  double sum = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) sum += luminance(image.rgb(x, y));
  return float(sum / (image.width * image.height));
}

TEST_F(EnvironmentCli, ALightlessFileIsLitByTheStudioEnvironmentInBothRenderers) {
  for (const char* renderer : {"path", "raster"}) {
    auto lit = render(renderer, "auto", std::string(renderer) + "-auto.exr");
    ASSERT_EQ(lit.exit_code, 0) << lit.output;
    EXPECT_THAT(lit.output, testing::HasSubstr("studio environment")) << "says what it did";
    EXPECT_GT(mean_luminance(read_image(path(std::string(renderer) + "-auto.exr"))), 0.05f);

    auto dark = render(renderer, "none", std::string(renderer) + "-none.exr");
    ASSERT_EQ(dark.exit_code, 0) << dark.output;
    EXPECT_EQ(mean_luminance(read_image(path(std::string(renderer) + "-none.exr"))), 0.f);
  }
}

TEST_F(EnvironmentCli, WhiteIsUniformRadianceOne) {
  // A camera ray that misses the box sees the environment's radiance itself: exactly 1.
  auto r = render("path", "white", "white.exr");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  Image image = read_image(path("white.exr"));
  Rgb corner = image.rgb(0, 0);
  EXPECT_FLOAT_EQ(corner.r, 1.f);
  EXPECT_FLOAT_EQ(corner.g, 1.f);
  EXPECT_FLOAT_EQ(corner.b, 1.f);
}

TEST_F(EnvironmentCli, ScenesWithTheirOwnLightAreLeftAlone) {
  // The built-in Cornell box is lit by its ceiling light only: no environment is added.
  auto r = test::run_cli("render --renderer direct --width 16 --height 16 --spp 1 -o " +
                         path("box.exr"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_THAT(r.output, testing::Not(testing::HasSubstr("studio environment")));
}

TEST_F(EnvironmentCli, AMissingMapIsAnErrorNamingIt) {
  auto r = render("path", path("no-such-map.exr"), "x.png");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.output, testing::HasSubstr("no-such-map.exr"));
  auto bad = test::run_cli("render --environment-intensity -1 -o " + path("y.png"));
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_THAT(bad.output, testing::HasSubstr("--environment-intensity"));
}

}  // namespace
}  // namespace obscura
