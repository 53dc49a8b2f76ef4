// `obscura render --glare` on both renderers, the vignetting options, and the refusals: glare on
// a camera without a sensor and malformed values.
#include <gtest/gtest.h>

#include <cmath>

#include "obscura/io/image_io.h"
#include "run_command.h"

namespace obscura {
namespace {

class GlareCli : public test::TempDirTest {
 protected:
  Image render(const std::string& arguments, const std::string& name) {
    auto r = test::run_cli("render -q --width 48 --height 32 --spp 4 " + arguments + " -o " +
                           path(name));
    EXPECT_EQ(r.exit_code, 0) << arguments << ": " << r.output;
    return read_image(path(name));
  }
};

double channel_sum(const Image& image, int c) {
  double sum = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) sum += image.at(x, y, c);
  return sum;
}

TEST_F(GlareCli, GlareSpreadsLightOnBothRenderersAndKeepsMostOfIt) {
  for (const char* renderer : {"path", "raster"}) {
    const std::string base = std::string("spheres-and-lights --renderer ") + renderer + " ";
    Image plain = render(base, "plain.exr");
    Image glared = render(base + "--glare-strength 50 --glare-radius 8", "glared.exr");
    double changed = 0;
    for (size_t i = 0; i < plain.data.size(); ++i)
      changed += std::abs(glared.data[i] - plain.data[i]);
    EXPECT_GT(changed, 1e-3 * plain.data.size()) << renderer;
    // Light near the frame's edges leaves it; the rest is kept.
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(channel_sum(glared, c) / channel_sum(plain, c), 1, 0.1) << renderer;
  }
}

TEST_F(GlareCli, VignettingDarkensTheCornersNotTheCentre) {
  const std::string base = "spheres-and-lights --renderer raster --focal-length 14 ";
  Image plain = render(base, "plain.exr");
  Image dark = render(base + "--natural-vignetting --fstop 4 --lens-barrel 5:10", "dark.exr");
  EXPECT_LT(dark.at(0, 0, 1), 0.5f * plain.at(0, 0, 1) + 1e-6f);
  EXPECT_NEAR(dark.at(24, 16, 1), plain.at(24, 16, 1), 0.02f * plain.at(24, 16, 1) + 1e-6f);
}

TEST_F(GlareCli, RefusesWhatItCannotDo) {
  test::expect_refusals(
      "render -q --width 16 --height 16 --spp 1 ",
      {{"spheres-and-lights --projection spherical --glare -o " + path("a.png"), "perspective"},
       {"spheres-and-lights --glare-strength -1 -o " + path("c.png"), "--glare-strength"},
       {"spheres-and-lights --glare-radius 0 -o " + path("d.png"), "--glare-radius"},
       {"spheres-and-lights --lens-barrel 5 -o " + path("e.png"), "--lens-barrel"},
       {"spheres-and-lights --fstop 2 --lens-barrel 5:10 -o " + path("f.png"),
        "aperture diameter"}});
}

}  // namespace
}  // namespace obscura
