// Costs bounded before the work starts, and cancels honoured after the render pass: a lens of
// too many surfaces or too much flare work is refused by name; a lens file that is a FIFO is
// refused (not read for ever); a glare radius beyond the image builds no PSF larger than the
// image; SIGTERM during the ghost flare of 100 lights stops it and writes the frame marked
// interrupted.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <OpenImageIO/imageio.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "run_command.h"

namespace obscura {
namespace {

namespace fs = std::filesystem;

class BoundedCostCli : public test::TempDirTest {
 protected:
  // A lens prescription of `surfaces` rows: a biconvex singlet, the stop, then flat glass plates
  // (each plate two surfaces), air last.
  std::string lens_file(int surfaces) {
    const std::string file = path("lens" + std::to_string(surfaces) + ".txt");
    std::ofstream out(file);
    out << "50 4 1.5168 20 64.2\n-50 2 1 20\n0 2 0 12\n";
    for (int row = 3; row < surfaces - 1; ++row)
      out << (row % 2 ? "0 0.5 1.5168 20 64.2\n" : "0 0.5 1 20\n");
    out << "0 40 1 20\n";
    return file;
  }
  // A scene of `count` point lights in front of the camera, over a floor.
  std::string lights_scene(int count) {
    const std::string file = path("lights.json");
    std::ofstream out(file);
    out << R"({"name": "lights", "materials": {"m": {"type": "diffuse", "reflectance": 0.5}},
      "objects": [{"name": "floor", "shape": "rectangle", "size": [8, 8], "material": "m"}],
      "cameras": [{"name": "c", "position": [0, 0, 2], "target": [0, 0, -3],
                   "focal_length_mm": 50}],
      "lights": [)";
    for (int i = 0; i < count; ++i)
      out << (i ? "," : "") << R"({"name": "l)" << i << R"(", "type": "point", "position": [)"
          << (i % 10 - 4.5) * 0.4 << ", " << (i / 10 - 4.5) * 0.3 << R"(, -3], "intensity": 50})";
    out << "]}";
    return file;
  }
};

TEST_F(BoundedCostCli, FlareOnTooManyLensSurfacesIsRefusedBeforeTracing) {
  auto result = test::run_cli("render " + lights_scene(1) +
                              " -q --width 16 --height 12 --spp 1 --flare --lens-file " +
                              lens_file(101) + " -o " + path("a.exr"));
  EXPECT_EQ(result.exit_code, 1) << result.output;
  EXPECT_NE(result.output.find("flare: the lens has 101 surfaces (up to 5050 ghosts)"),
            std::string::npos)
      << result.output;
  EXPECT_FALSE(fs::exists(path("a.exr")));
}

TEST_F(BoundedCostCli, FlareWorkOfGhostsTimesLightsIsRefusedBeforeTracing) {
  // 64 surfaces (63 reflecting: 1,953 ghosts) × 100 lights × 64 surfaces: far over the bound.
  auto result = test::run_cli("render " + lights_scene(100) +
                              " -q --width 16 --height 12 --spp 1 --flare --lens-file " +
                              lens_file(64) + " -o " + path("a.exr"));
  EXPECT_EQ(result.exit_code, 1) << result.output;
  EXPECT_NE(result.output.find("bright lights"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("fewer lights, or a simpler lens"), std::string::npos)
      << result.output;
}

TEST_F(BoundedCostCli, LensFilesAreCheckedLikeEveryInput) {
  ASSERT_EQ(::mkfifo(path("lens.txt").c_str(), 0600), 0);
  // (timeout: before the fix the reader blocked on the FIFO for ever.)
  auto result = test::run_shell("timeout 120 " +
                                test::cli_command_line("render -q --width 16 --height 12 --spp 1 "
                                                       "--lens-file " +
                                                       path("lens.txt") + " -o " + path("a.exr")));
  EXPECT_EQ(result.exit_code, 2) << result.output;  // the option's file: a usage error
  EXPECT_NE(result.output.find(path("lens.txt") + ": is not a regular file"), std::string::npos)
      << result.output;
  EXPECT_TRUE(fs::is_fifo(path("lens.txt")));
}

// A 4096-pixel radius on a 16 × 12 frame builds a PSF of the frame's size (33 × 33), not
// 8193 × 8193 (2.45 GB before): it runs within a 1.2 GB address space.
TEST_F(BoundedCostCli, GlareRadiusIsNeverLargerThanTheImageNeeds) {
  auto result = test::run_shell(
      test::address_space_limit(1'200'000) +
      test::cli_command_line("render spheres-and-lights -q --width 16 --height 12 --spp 1 "
                             "--glare --glare-radius 4096 -o " +
                             path("g.exr")));
  EXPECT_EQ(result.exit_code, 0) << result.output;
  EXPECT_TRUE(fs::exists(path("g.exr")));
}

// The flare of 100 lights takes tens of seconds; SIGTERM three seconds in stops it (the render
// after it stops on the same flag), and the frame is written marked interrupted, naming what the
// cancel left out.
TEST_F(BoundedCostCli, SigtermDuringTheFlareStopsAndMarksTheFrame) {
  const std::string out = path("f.exr");
  auto result = test::run_shell(
      test::cli_command_line("render " + lights_scene(100) +
                             " --width 160 --height 120 --spp 1 --lens double-gauss-50mm "
                             "--flare -o " +
                             out) +
      " & sleep 3; kill -TERM $!; wait $!");
  EXPECT_EQ(result.exit_code, 143) << result.output;  // 128 + SIGTERM
  EXPECT_NE(result.output.find("left out: flare"), std::string::npos) << result.output;
  auto in = OIIO::ImageInput::open(out);
  ASSERT_TRUE(in) << OIIO::geterror();
  EXPECT_EQ(in->spec().get_string_attribute("obscura:partial"), "interrupted");
  EXPECT_NE(in->spec().get_string_attribute("ImageDescription").find("left out: flare"),
            std::string::npos);
}

}  // namespace
}  // namespace obscura
