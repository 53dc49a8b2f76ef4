// `obscura render --renderer raster` and its options, run as a user would.
#include <gtest/gtest.h>

#include <filesystem>

#include "obscura/io/image_io.h"
#include "run_command.h"

namespace obscura {
namespace {

namespace fs = std::filesystem;

class RasterCli : public test::TempDirTest {};

TEST_F(RasterCli, RendersTheCornellBoxWithWallsWhereTheyBelong) {
  auto r = test::run_cli("render --renderer raster --width 64 --height 64 -o " + path("box.png"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find(path("box.png")), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("64x64 (raster)"), std::string::npos) << r.output;
  Image image = read_image(path("box.png"));
  ASSERT_EQ(image.width, 64);
  ASSERT_EQ(image.height, 64);
  // The red wall on the left, the green one on the right, lit by the ceiling light.
  for (int y = 20; y < 44; y += 4) {
    Rgb left = image.rgb(4, y), right = image.rgb(59, y);
    EXPECT_GT(left.r, 2 * left.g) << "left wall at row " << y;
    EXPECT_GT(left.r, 0.1f);
    EXPECT_GT(right.g, 1.5f * right.r) << "right wall at row " << y;
    EXPECT_GT(right.g, 0.1f);
  }
  EXPECT_GT(image.rgb(32, 9).r, 0.99f);  // the light itself
}

TEST_F(RasterCli, IsDeterministicForAnyThreadCountAndWritesItsOutputs) {
  const std::string common =
      "render spheres-and-lights -q --renderer raster --msaa 4 --width 96 --height 54 ";
  auto one = test::run_cli(common + "--threads 1 --aovs -o " + path("one.exr"));
  auto two = test::run_cli(common + "--threads 2 -o " + path("two.exr"));
  ASSERT_EQ(one.exit_code, 0) << one.output;
  ASSERT_EQ(two.exit_code, 0) << two.output;
  Image a = read_image(path("one.exr")), b = read_image(path("two.exr"));
  EXPECT_EQ(a.data, b.data);
  for (const char* aov : {"one.depth.exr", "one.normal.exr", "one.id.exr"})
    EXPECT_TRUE(fs::exists(path(aov))) << aov << "\n" << one.output;
  Image id = read_image(path("one.id.exr"));
  EXPECT_EQ(id.at(0, 0, 0), -1.f);  // the sky above the floor: background
  EXPECT_GE(id.at(48, 40, 0), 0.f);
}

TEST_F(RasterCli, EveryShadingModeAndTheWireframeRender) {
  for (const char* shading : {"flat", "gouraud", "phong", "blinn-phong"}) {
    auto r = test::run_cli(std::string("render bunny -q --renderer raster --cull --wireframe ") +
                           "--width 32 --height 32 --shading " + shading + " -o " + path("b.png"));
    EXPECT_EQ(r.exit_code, 0) << shading << ": " << r.output;
  }
}

TEST_F(RasterCli, BadOptionsAreUsageErrors) {
  struct Case {
    const char* arguments;
    const char* message;
  };
  for (const Case& c :
       {Case{"--renderer raster --msaa 2", "--msaa must be 1, 4 or 8 samples; got 2"},
        Case{"--renderer raster --shading toon",
             "--shading must be flat, gouraud, phong or blinn-phong; got 'toon'"},
        Case{"--renderer raster --shadow-map -1",
             "--shadow-map: expected an integer from 0 to 16384; got '-1'"},
        Case{"--renderer path --wireframe", "--wireframe applies to --renderer raster only"}}) {
    auto r = test::run_cli(std::string("render ") + c.arguments + " -o " + path("x.png"));
    EXPECT_EQ(r.exit_code, 2) << c.arguments << ": " << r.output;
    EXPECT_NE(r.output.find(c.message), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(path("x.png")));
  }
}

}  // namespace
}  // namespace obscura
