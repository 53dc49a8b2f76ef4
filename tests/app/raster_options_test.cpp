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

// An orthographic camera with its far plane at infinity (what scene files default to, and
// `--far inf`): the rasterizer fits a finite far plane to the scene (glOrtho's own limit is
// singular) and draws every still built-in scene; its silhouettes are the tracer's.
TEST_F(RasterCli, OrthographicCamerasWithAFarPlaneAtInfinityDraw) {
  for (const char* scene : {"cornell-box", "cornell-box-obj", "spheres-and-lights",
                            "depth-of-field", "bunny", "gltf-spheres"}) {
    SCOPED_TRACE(scene);
    const std::string common = std::string("render ") + scene +
                               " -q --projection orthographic --far inf --width 48 --height 48 ";
    auto drawn = test::run_cli(common + "--renderer raster --aovs -o " + path("r.exr"));
    ASSERT_EQ(drawn.exit_code, 0) << drawn.output;
    // One sample at each pixel's centre, where the rasterizer takes its ids.
    auto traced = test::run_cli(common + "--renderer direct --spp 1 --filter box --filter-radius " +
                                "0.01 --aovs -o " + path("t.exr"));
    ASSERT_EQ(traced.exit_code, 0) << traced.output;
    const Image raster_id = read_image(path("r.id.exr")), trace_id = read_image(path("t.id.exr"));
    ASSERT_EQ(raster_id.data.size(), trace_id.data.size());
    size_t same = 0, covered = 0;
    for (size_t p = 0; p < raster_id.data.size(); ++p) {
      same += raster_id.data[p] == trace_id.data[p];
      covered += trace_id.data[p] >= 0;
    }
    EXPECT_GT(covered, 0u);  // something is in view
    // A pixel whose centre lies on an edge may go either way.
    EXPECT_GE(double(same) / double(raster_id.data.size()), 0.99);
  }
  auto bad = test::run_cli("render -q --far nan -o " + path("x.png"));
  EXPECT_EQ(bad.exit_code, 2) << bad.output;
}

}  // namespace
}  // namespace obscura
