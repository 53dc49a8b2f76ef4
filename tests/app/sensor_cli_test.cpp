// `obscura render --raw-sensor` and `-o x.dng`: LibRaw (Debian's libraw-bin, an independent DNG
// reader) reads the file Obscura writes — the CFA pattern, size, black and white levels — and
// develops it; the ground truth is written beside it; a full disk keeps the old files; the
// capture is the same bytes for any thread count and under MPI; bad values name their field.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>

#include "app/mpi_launcher.h"
#include "obscura/io/image_io.h"
#include "run_command.h"
#include "test_paths.h"

namespace obscura {
namespace {

namespace fs = std::filesystem;

const char* kScene = "cornell-box -q --width 64 --height 48 --spp 2 ";

class SensorCli : public test::TempDirTest {
 protected:
  void render(const std::string& arguments) {
    auto r = test::run_cli(std::string("render ") + kScene + arguments);
    ASSERT_EQ(r.exit_code, 0) << arguments << ": " << r.output;
  }
};

bool has_libraw() {
  return test::run_shell("command -v raw-identify dcraw_emu").exit_code == 0;
}

TEST_F(SensorCli, LibRawReadsWhatWasWritten) {
  if (!has_libraw()) GTEST_SKIP() << "LibRaw's tools are not installed (scripts/setup: libraw-bin)";
  const struct {
    const char* cfa;
    int black, bits;
    double gain;
  } cases[] = {{"RGGB", 256, 14, 0.5},
               {"BGGR", 512, 12, 0.25},
               {"GRBG", 64, 16, 1},
               {"GBRG", 1000, 14, 0.5}};
  for (const auto& c : cases) {
    const std::string dng = path(std::string(c.cfa) + ".dng");
    // The Cornell box's light is dim (about 1 cd/m²): a 5-minute exposure fills the wells.
    render("--shutter 0:300 --raw-sensor cfa=" + std::string(c.cfa) +
           ",black_level_dn=" + std::to_string(c.black) + ",adc_bits=" + std::to_string(c.bits) +
           ",full_well_e=8000,gain_dn_per_e=" + std::to_string(c.gain) + " -o " + dng);
    const int white = std::min((1 << c.bits) - 1, int(std::lround(c.black + c.gain * 8000)));
    auto id = test::run_shell("raw-identify -v " + test::quoted(dng));
    ASSERT_EQ(id.exit_code, 0) << id.output;
    EXPECT_NE(id.output.find("Camera: Obscura Raw sensor"), std::string::npos) << id.output;
    EXPECT_NE(id.output.find("DNG Version: 1.4.0.0"), std::string::npos) << id.output;
    EXPECT_TRUE(std::regex_search(id.output, std::regex("Full size: +64 x 48"))) << id.output;
    EXPECT_NE(id.output.find(std::string("Filter pattern: ") + c.cfa + c.cfa), std::string::npos)
        << id.output;
    EXPECT_NE(id.output.find("black: " + std::to_string(c.black) + "\n"), std::string::npos)
        << id.output;
    EXPECT_NE(id.output.find("DNG Illuminant 1: D65"), std::string::npos) << id.output;
    EXPECT_NE(id.output.find("DNG Illuminant 2: Illuminant A"), std::string::npos) << id.output;
    // raw-identify does not print the white level: dcraw_emu shows it. Developed linearly in the
    // camera's own colours with unit white balance (-4 -o 0 -r 1 1 1 1), a green photosite
    // reads (raw − black) / (white − black) of 65535 where LibRaw took the levels the file says.
    auto dev = test::run_shell("dcraw_emu -4 -o 0 -r 1 1 1 1 " + test::quoted(dng));
    ASSERT_EQ(dev.exit_code, 0) << dev.output;
    ASSERT_TRUE(fs::exists(dng + ".ppm")) << dev.output;
    const Image developed = read_image(dng + ".ppm");
    ASSERT_EQ(developed.width, 64);
    ASSERT_EQ(developed.height, 48);
    ImageMetadata metadata;
    const Image raw = read_exr_data(path(std::string(c.cfa) + ".raw.exr"), metadata);
    ASSERT_EQ(raw.channels, 1);
    int greens = 0, lit = 0;
    for (int y = 0; y < 48; ++y)
      for (int x = 0; x < 64; ++x) {
        if (c.cfa[(y % 2) * 2 + x % 2] != 'G') continue;
        const double expected =
            std::clamp((raw.at(x, y, 0) - c.black) / double(white - c.black), 0.0, 1.0);
        EXPECT_NEAR(developed.at(x, y, 1), expected, 2.0 / 65535) << c.cfa << " " << x << "," << y;
        ++greens;
        lit += expected > 0.05;
      }
    EXPECT_EQ(greens, 64 * 48 / 2);
    EXPECT_GT(lit, greens / 4) << "the frame is lit enough to test the levels";
    // The ground truth beside it.
    for (const char* name : {"raw", "irradiance", "electrons"})
      EXPECT_TRUE(fs::exists(path(std::string(c.cfa) + "." + name + ".exr"))) << name;
    for (float v : raw.data) ASSERT_TRUE(v >= 0 && v <= float(white));
  }
}

TEST_F(SensorCli, LibRawDevelopsTheColoursRendered) {
  // The DNG's colour tags (ColorMatrix1 for D65, AsShotNeutral) as LibRaw uses them: uniform
  // fields of known linear Rec.709 colour, captured bright (shot noise ~1 %), developed by
  // dcraw_emu to linear sRGB (-4 -o 1) with the as-shot white balance (-w), give back the
  // colour's channel ratios — a grey within 1.5 %, saturated colours within 5 %.
  if (!has_libraw()) GTEST_SKIP() << "LibRaw's tools are not installed (scripts/setup: libraw-bin)";
  const struct {
    double r, g, b, tolerance;
  } colours[] = {{0.5, 0.5, 0.5, 0.015}, {0.6, 0.3, 0.15, 0.05}, {0.2, 0.5, 0.7, 0.05}};
  for (const auto& c : colours) {
    const std::string scene = path("colour.json"), dng = path("colour.dng");
    std::ofstream(scene, std::ios::trunc)
        << R"({"environment": {"color": [)" << c.r << ", " << c.g << ", " << c.b
        << R"(]}, "cameras": [{"name": "cam", "type": "perspective", "position": [0, 0, 0],
              "target": [0, 0, -1]}]})";
    auto r = test::run_cli("render -q " + scene +
                           " --width 64 --height 48 --spp 1 --shutter 0:200 --raw-sensor "
                           "full_well_e=60000,adc_bits=16 -o " +
                           dng);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    auto dev = test::run_shell("dcraw_emu -4 -o 1 -w " + test::quoted(dng));
    ASSERT_EQ(dev.exit_code, 0) << dev.output;
    const Image developed = read_image(dng + ".ppm");
    double mean[3] = {0, 0, 0};
    int n = 0;
    for (int y = 8; y < 40; ++y)
      for (int x = 8; x < 56; ++x, ++n)
        for (int ch = 0; ch < 3; ++ch) mean[ch] += developed.at(x, y, ch);
    ASSERT_GT(mean[1] / n, 0.1) << "exposed well above black";
    EXPECT_NEAR((mean[0] / mean[1]) / (c.r / c.g), 1, c.tolerance)
        << c.r << "," << c.g << "," << c.b;
    EXPECT_NEAR((mean[2] / mean[1]) / (c.b / c.g), 1, c.tolerance)
        << c.r << "," << c.g << "," << c.b;
  }
}

TEST_F(SensorCli, LinearDngIsDevelopedToo) {
  if (!has_libraw()) GTEST_SKIP() << "LibRaw's tools are not installed (scripts/setup: libraw-bin)";
  const std::string dng = path("linear.dng");
  render("--raw-sensor on --linear-dng -o " + dng);
  auto id = test::run_shell("raw-identify -v " + test::quoted(dng));
  ASSERT_EQ(id.exit_code, 0) << id.output;
  EXPECT_TRUE(std::regex_search(id.output, std::regex("Full size: +64 x 48"))) << id.output;
  EXPECT_EQ(id.output.find("Filter pattern"), std::string::npos) << id.output;  // no CFA
  auto dev = test::run_shell("dcraw_emu " + test::quoted(dng));
  ASSERT_EQ(dev.exit_code, 0) << dev.output;
  EXPECT_TRUE(fs::exists(dng + ".ppm"));
}

TEST_F(SensorCli, MonochromeDngIsOnePlane) {
  if (!has_libraw()) GTEST_SKIP() << "LibRaw's tools are not installed (scripts/setup: libraw-bin)";
  const std::string dng = path("mono.dng");
  render("--raw-sensor cfa=mono -o " + dng);
  auto id = test::run_shell("raw-identify -v " + test::quoted(dng));
  ASSERT_EQ(id.exit_code, 0) << id.output;
  EXPECT_NE(id.output.find("Raw colors: 1\n"), std::string::npos) << id.output;
  auto dev = test::run_shell("dcraw_emu " + test::quoted(dng));
  ASSERT_EQ(dev.exit_code, 0) << dev.output;
  EXPECT_TRUE(fs::exists(dng + ".pgm"));  // a grey image
}

TEST_F(SensorCli, SameCaptureForAnyThreadCount) {
  render("--threads 1 --raw-sensor on -o " + path("one.dng"));
  render("--raw-sensor on -o " + path("many.dng"));
  ImageMetadata m;
  EXPECT_EQ(read_exr_data(path("one.raw.exr"), m).data,
            read_exr_data(path("many.raw.exr"), m).data);
  render("--raw-sensor on --seed 5 -o " + path("other.dng"));
  EXPECT_NE(read_exr_data(path("one.raw.exr"), m).data,
            read_exr_data(path("other.raw.exr"), m).data);
}

TEST_F(SensorCli, DevelopedOutputsAndMetering) {
  // Any other format is the capture developed by the reference pipeline; --metering reports the
  // EV100 on stderr and in the file.
  auto r =
      test::run_cli(std::string("render ") + kScene +
                    "--raw-sensor on --demosaic bilinear --metering spot -o " + path("dev.exr"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(r.output.find("metered EV100"), std::string::npos) << r.output;  // -q: quiet
  ImageMetadata metadata;
  const Image image = read_exr_data(path("dev.exr"), metadata);
  EXPECT_EQ(image.width, 64);
  bool metered = false;
  for (const auto& [name, value] : metadata.attributes) metered |= name == "obscura:metered_ev100";
  EXPECT_TRUE(metered);
}

TEST_F(SensorCli, AutoExposurePrintsItsChoice) {
  auto r = test::run_cli(
      "render cornell-box --width 32 --height 24 --spp 2 --exposure-mode auto "
      "-o " +
      path("auto.png"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("auto exposure: metered EV100 "), std::string::npos) << r.output;
  EXPECT_NE(r.output.find(" (average): f/"), std::string::npos) << r.output;
}

TEST_F(SensorCli, FullDiskKeepsTheOldFiles) {
  const std::string dng = path("keep.dng");
  render("--raw-sensor on -o " + dng);
  const std::string good = "the user's good file";
  std::ofstream(dng, std::ios::binary | std::ios::trunc) << good;
  auto r =
      test::run_shell("ulimit -f 1; " + test::cli_command_line(std::string("render ") + kScene +
                                                               "--raw-sensor on -o " + dng));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("File too large"), std::string::npos) << r.output;
  std::ifstream in(dng, std::ios::binary);
  const std::string kept((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(kept, good);
  // The ground truth of the first render is kept too, and no temporary file is left behind.
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir_))
    names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"keep.dng", "keep.electrons.exr",
                                             "keep.irradiance.exr", "keep.raw.exr"}));
}

TEST_F(SensorCli, BadValuesNameTheirField) {
  test::expect_refusals(std::string("render ") + kScene + "-o " + path("bad.dng") + " ",
                        {{"--raw-sensor read_noise_e=-1", "sensor.read_noise_e"},
                         {"--raw-sensor full_well_e=0", "sensor.full_well_e"},
                         {"--raw-sensor qe_red=1.5", "sensor.qe_red"},
                         {"--raw-sensor adc_bits=0", "sensor.adc_bits"},
                         {"--raw-sensor adc_bits=64", "sensor.adc_bits"},
                         {"--raw-sensor prnu=nan", "sensor.prnu"},
                         {"--raw-sensor cfa=XYZW", "sensor.cfa"},
                         {"--raw-sensor full_wel=3", "unknown sensor field"},
                         {"--demosaic nearest", "expected bilinear or malvar"},
                         {"--metering matrix", "expected average, center-weighted or spot"},
                         {"--raw-sensor on --frames 0:1", "do not take --frames"}});
}

TEST_F(SensorCli, JsonSensorBlock) {
  const std::string scene = path("scene.json");
  std::ofstream(scene) << R"({"environment": {"color": 0.5},
    "cameras": [{"name": "cam", "type": "perspective", "position": [0, 0, 0],
                 "target": [0, 0, -1], "sensor": {"cfa": "GBRG", "black_level_dn": 300,
                 "full_well_e": 0}}]})";
  auto r = test::run_cli("render -q " + scene + " --width 48 --height 32 -o " + path("j.dng"));
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("$.cameras[0].sensor.full_well_e: must be positive"), std::string::npos)
      << r.output;
  std::ofstream(scene, std::ios::trunc) << R"({"environment": {"color": 0.5},
    "cameras": [{"name": "cam", "type": "perspective", "position": [0, 0, 0],
                 "target": [0, 0, -1], "sensor": {"cfa": "GBRG", "black_level_dn": 300}}]})";
  r = test::run_cli("render -q " + scene + " --width 48 --height 32 -o " + path("j.dng"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  if (!has_libraw()) GTEST_SKIP() << "LibRaw's tools are not installed (scripts/setup: libraw-bin)";
  auto id = test::run_shell("raw-identify -v " + test::quoted(path("j.dng")));
  EXPECT_NE(id.output.find("Filter pattern: GBRG"), std::string::npos) << id.output;
  EXPECT_NE(id.output.find("black: 300\n"), std::string::npos) << id.output;
}

class SensorMpi : public test::MpiCliTest {};

TEST_F(SensorMpi, RanksCaptureTheSameBytes) {
  auto one =
      test::run_cli(std::string("render ") + kScene + "--raw-sensor on -o " + path("one.dng"));
  ASSERT_EQ(one.exit_code, 0) << one.output;
  auto two = test::run_shell(
      mpirun_obscura(2, std::string("render ") + kScene + "--raw-sensor on -o " + path("two.dng")));
  ASSERT_EQ(two.exit_code, 0) << two.output;
  ImageMetadata m;
  EXPECT_EQ(read_exr_data(path("one.raw.exr"), m).data, read_exr_data(path("two.raw.exr"), m).data);
}

}  // namespace
}  // namespace obscura
