// `obscura render --sensor` and `-o x.dng`: LibRaw (Debian's libraw-bin, an independent DNG
// reader) reads the file Obscura writes — the CFA pattern, size, black and white levels — and
// develops it; the ground truth is written beside it; a full disk keeps the old files; the
// capture is the same bytes for any thread count and under MPI; bad values name their field.
#include <gtest/gtest.h>

#include <algorithm>
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
  } cases[] = {{"RGGB", 256, 14}, {"BGGR", 512, 12}, {"GRBG", 64, 16}, {"GBRG", 1000, 14}};
  for (const auto& c : cases) {
    const std::string dng = path(std::string(c.cfa) + ".dng");
    render("--sensor cfa=" + std::string(c.cfa) + ",black_level_dn=" + std::to_string(c.black) +
           ",adc_bits=" + std::to_string(c.bits) + ",full_well_e=8000,gain_dn_per_e=0.5 -o " + dng);
    const int white = std::min((1 << c.bits) - 1, c.black + 4000);
    auto id = test::run_shell("raw-identify -v " + test::quoted(dng));
    ASSERT_EQ(id.exit_code, 0) << id.output;
    EXPECT_NE(id.output.find("Obscura"), std::string::npos) << id.output;
    EXPECT_NE(id.output.find("64x48"), std::string::npos) << id.output;
    EXPECT_NE(id.output.find(std::string("Filter pattern: ") + c.cfa), std::string::npos)
        << id.output;
    EXPECT_NE(id.output.find("black=" + std::to_string(c.black)), std::string::npos) << id.output;
    EXPECT_NE(id.output.find("white=" + std::to_string(white)), std::string::npos) << id.output;
    // dcraw_emu develops it (to a PPM beside it) at the file's size.
    auto dev = test::run_shell("dcraw_emu " + test::quoted(dng));
    ASSERT_EQ(dev.exit_code, 0) << dev.output;
    ASSERT_TRUE(fs::exists(dng + ".ppm")) << dev.output;
    const Image developed = read_image(dng + ".ppm");
    EXPECT_EQ(developed.width, 64);
    EXPECT_EQ(developed.height, 48);
    // The ground truth beside it.
    for (const char* name : {"raw", "irradiance", "electrons"}) {
      const std::string truth = path(std::string(c.cfa) + "." + name + ".exr");
      ASSERT_TRUE(fs::exists(truth)) << truth;
    }
    ImageMetadata metadata;
    const Image raw = read_exr_data(path(std::string(c.cfa) + ".raw.exr"), metadata);
    ASSERT_EQ(raw.channels, 1);
    for (float v : raw.data) ASSERT_TRUE(v >= 0 && v <= float(white));
  }
}

TEST_F(SensorCli, LinearDngIsDevelopedToo) {
  if (!has_libraw()) GTEST_SKIP() << "LibRaw's tools are not installed (scripts/setup: libraw-bin)";
  const std::string dng = path("linear.dng");
  render("--sensor on --linear-dng -o " + dng);
  auto id = test::run_shell("raw-identify -v " + test::quoted(dng));
  ASSERT_EQ(id.exit_code, 0) << id.output;
  EXPECT_NE(id.output.find("64x48"), std::string::npos) << id.output;
  auto dev = test::run_shell("dcraw_emu " + test::quoted(dng));
  ASSERT_EQ(dev.exit_code, 0) << dev.output;
  EXPECT_TRUE(fs::exists(dng + ".ppm"));
}

TEST_F(SensorCli, SameCaptureForAnyThreadCount) {
  render("--threads 1 --sensor on -o " + path("one.dng"));
  render("--sensor on -o " + path("many.dng"));
  ImageMetadata m;
  EXPECT_EQ(read_exr_data(path("one.raw.exr"), m).data,
            read_exr_data(path("many.raw.exr"), m).data);
  render("--sensor on --seed 5 -o " + path("other.dng"));
  EXPECT_NE(read_exr_data(path("one.raw.exr"), m).data,
            read_exr_data(path("other.raw.exr"), m).data);
}

TEST_F(SensorCli, DevelopedOutputsAndMetering) {
  // Any other format is the capture developed by the reference pipeline; --metering reports the
  // EV100 on stderr and in the file.
  auto r = test::run_cli(std::string("render ") + kScene +
                         "--sensor on --demosaic bilinear --metering spot -o " + path("dev.exr"));
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
  render("--sensor on -o " + dng);
  const std::string good = "the user's good file";
  std::ofstream(dng, std::ios::binary | std::ios::trunc) << good;
  auto r =
      test::run_shell("ulimit -f 1; " + test::cli_command_line(std::string("render ") + kScene +
                                                               "--sensor on -o " + dng));
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
                        {{"--sensor read_noise_e=-1", "sensor.read_noise_e"},
                         {"--sensor full_well_e=0", "sensor.full_well_e"},
                         {"--sensor qe_red=1.5", "sensor.qe_red"},
                         {"--sensor adc_bits=0", "sensor.adc_bits"},
                         {"--sensor adc_bits=64", "sensor.adc_bits"},
                         {"--sensor prnu=nan", "sensor.prnu"},
                         {"--sensor cfa=XYZW", "sensor.cfa"},
                         {"--sensor full_wel=3", "unknown sensor field"},
                         {"--demosaic nearest", "expected bilinear or malvar"},
                         {"--metering matrix", "expected average, center-weighted or spot"},
                         {"--sensor on --frames 0:1", "do not take --frames"}});
}

TEST_F(SensorCli, JsonSensorBlock) {
  const std::string scene = path("scene.json");
  std::ofstream(scene) << R"({"environment": {"color": 0.5},
    "cameras": [{"name": "cam", "type": "perspective", "position": [0, 0, 0],
                 "target": [0, 0, -1], "sensor": {"cfa": "GBRG", "black_level_dn": 300,
                 "full_well_e": 0}}]})";
  auto r = test::run_cli("render -q " + scene + " --width 16 --height 16 -o " + path("j.dng"));
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("$.cameras[0].sensor.full_well_e: must be positive"), std::string::npos)
      << r.output;
  std::ofstream(scene, std::ios::trunc) << R"({"environment": {"color": 0.5},
    "cameras": [{"name": "cam", "type": "perspective", "position": [0, 0, 0],
                 "target": [0, 0, -1], "sensor": {"cfa": "GBRG", "black_level_dn": 300}}]})";
  r = test::run_cli("render -q " + scene + " --width 16 --height 16 -o " + path("j.dng"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  if (!has_libraw()) GTEST_SKIP() << "LibRaw's tools are not installed (scripts/setup: libraw-bin)";
  auto id = test::run_shell("raw-identify -v " + test::quoted(path("j.dng")));
  EXPECT_NE(id.output.find("Filter pattern: GBRG"), std::string::npos) << id.output;
  EXPECT_NE(id.output.find("black=300"), std::string::npos) << id.output;
}

class SensorMpi : public test::MpiCliTest {};

TEST_F(SensorMpi, RanksCaptureTheSameBytes) {
  auto one = test::run_cli(std::string("render ") + kScene + "--sensor on -o " + path("one.dng"));
  ASSERT_EQ(one.exit_code, 0) << one.output;
  auto two = test::run_shell(
      mpirun_obscura(2, std::string("render ") + kScene + "--sensor on -o " + path("two.dng")));
  ASSERT_EQ(two.exit_code, 0) << two.output;
  ImageMetadata m;
  EXPECT_EQ(read_exr_data(path("one.raw.exr"), m).data, read_exr_data(path("two.raw.exr"), m).data);
}

}  // namespace
}  // namespace obscura
