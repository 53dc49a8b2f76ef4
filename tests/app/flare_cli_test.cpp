// `obscura render --flare` on a lens-system camera, on both renderers: the ghosts add light and
// a coating weakens them; and the refusals: a camera without lens surfaces, a bad
// --lens-coating, --lens-coating without a lens system.
#include <gtest/gtest.h>

#include "obscura/io/image_io.h"
#include "run_command.h"

namespace obscura {
namespace {

class FlareCli : public test::TempDirTest {
 protected:
  Image render(const std::string& arguments, const std::string& name) {
    auto r = test::run_cli("render -q --width 64 --height 40 --spp 1 " + arguments + " -o " +
                           path(name));
    EXPECT_EQ(r.exit_code, 0) << arguments << ": " << r.output;
    return read_image(path(name));
  }
};

double total(const Image& image) {
  double sum = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      for (int c = 0; c < 3; ++c) sum += image.at(x, y, c);
  return sum;
}

TEST_F(FlareCli, FlareAddsGhostsOnBothRenderersAndACoatingWeakensThem) {
  for (const char* renderer : {"path", "raster"}) {
    const std::string base = std::string("spheres-and-lights --renderer ") + renderer +
                             " --lens double-gauss-50mm --fstop 8 --seed 3 ";
    const Image plain = render(base, "plain.exr");
    const Image bare = render(base + "--flare --lens-coating none", "bare.exr");
    const Image coated = render(base + "--flare --lens-coating quarter-wave", "coated.exr");
    const double ghosts_bare = total(bare) - total(plain),
                 ghosts_coated = total(coated) - total(plain);
    EXPECT_GT(ghosts_bare, 0) << renderer;
    EXPECT_GT(ghosts_coated, 0) << renderer;
    EXPECT_LT(ghosts_coated, 0.5 * ghosts_bare) << renderer;
  }
}

TEST_F(FlareCli, RefusesWhatItCannotDo) {
  test::expect_refusals(
      "render -q --width 16 --height 16 --spp 1 ",
      {{"spheres-and-lights --flare -o " + path("a.png"), "--flare"},
       {"spheres-and-lights --lens double-gauss-50mm --lens-coating wax -o " + path("c.png"),
        "--lens-coating"},
       {"spheres-and-lights --lens-coating none -o " + path("d.png"), "--lens-coating"}});
}

}  // namespace
}  // namespace obscura
