// The `color` and `image` subcommands, run as a user would: exit codes, output, errors.
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "obscura/io/image_io.h"
#include "run_command.h"
#include "test_paths.h"

namespace obscura {
namespace {

namespace fs = std::filesystem;

struct Result {
  int exit_code;
  std::string out;  // stdout and stderr together
};

// Runs `obscura <arguments>`, with `input` (if any) on standard input.
Result run(const std::string& arguments, const std::string& input = "") {
  std::string redirect;
  if (!input.empty()) {
    static const std::string dir = test::make_temp_dir("obscura-color-cli-stdin");
    static int count = 0;
    std::string file = dir + "/input" + std::to_string(count++) + ".txt";
    std::ofstream(file) << input;
    redirect = " < " + file;
  }
  test::CommandResult r = test::run_cli(arguments + redirect);
  return {r.exit_code, r.output};
}

std::vector<double> numbers(const std::string& line) {
  std::istringstream in(line);
  std::vector<double> v;
  for (double x; in >> x;) v.push_back(x);
  return v;
}

TEST(ColorCli, ConvertPrintsValuesAndGamut) {
  Result r = run("color convert --from srgb --to display-p3 1 0 0");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  std::vector<double> v = numbers(r.out.substr(0, r.out.find('\n')));
  ASSERT_EQ(v.size(), 3u);
  // sRGB red in Display P3 (shared vectors; OpenColorIO's probe gives the same 0.917488).
  EXPECT_NEAR(v[0], 0.917488, 1e-5);
  EXPECT_NEAR(v[1], 0.200287, 1e-5);
  EXPECT_NEAR(v[2], 0.138561, 1e-5);
  EXPECT_NE(r.out.find("in gamut of display-p3: yes"), std::string::npos) << r.out;

  Result oog = run("color convert --from display-p3 --to srgb 1 0 0");
  EXPECT_NE(oog.out.find("in gamut of srgb: no"), std::string::npos) << oog.out;
  Result negative = run("color convert --from srgb-linear --to srgb -0.5 0.25 1");
  ASSERT_EQ(negative.exit_code, 0) << negative.out;
  EXPECT_NEAR(numbers(negative.out)[0], -0.735357, 1e-5);  // odd-symmetric extension
}

TEST(ColorCli, ConvertBatchFromStdinOneResultPerLine) {
  Result r = run("color convert --from srgb --to srgb-linear", "1 1 1\n0.5 0.5 0.5\n\n0 0 0\n");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  std::istringstream lines(r.out);
  std::vector<std::string> out;
  for (std::string line; std::getline(lines, line);) out.push_back(line);
  ASSERT_EQ(out.size(), 3u) << r.out;
  EXPECT_NEAR(numbers(out[1])[0], 0.2140411, 1e-6);

  Result json = run("color convert --from srgb --to lab-d50 --json", "1 1 1\n");
  ASSERT_EQ(json.exit_code, 0) << json.out;
  nlohmann::json j = nlohmann::json::parse(json.out);
  EXPECT_NEAR(j["output"][0].get<double>(), 100, 1e-6);
  EXPECT_EQ(j["in_gamut"], true);

  Result bad = run("color convert --from srgb --to xyz-d65", "1 2\n");
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_NE(bad.out.find("stdin:1"), std::string::npos) << bad.out;
}

TEST(ColorCli, BadInputIsAUsageErrorWithAClearMessage) {
  Result unknown = run("color convert --from srgb --to cielab 1 0 0");
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_NE(unknown.out.find("unknown space 'cielab'"), std::string::npos) << unknown.out;
  Result count = run("color convert --from srgb --to xyz-d65 1 0");
  EXPECT_EQ(count.exit_code, 2);
  EXPECT_NE(count.out.find("takes 3 values; got 2"), std::string::npos) << count.out;
  Result nan = run("color convert --from srgb --to xyz-d65 nan 0 0");
  EXPECT_EQ(nan.exit_code, 2);
  EXPECT_NE(nan.out.find("finite"), std::string::npos) << nan.out;
  Result wavelength = run("color wavelength -- -570");
  EXPECT_EQ(wavelength.exit_code, 2);
  EXPECT_NE(wavelength.out.find("positive"), std::string::npos) << wavelength.out;
  Result tonemap =
      run("image convert " + test::source_path("CMakeLists.txt") + " x.png --tonemap filmic");
  EXPECT_EQ(tonemap.exit_code, 2);
  EXPECT_NE(tonemap.out.find("filmic"), std::string::npos) << tonemap.out;
}

TEST(ColorCli, WavelengthAndTemperature) {
  Result yellow = run("color wavelength 570 --json");
  ASSERT_EQ(yellow.exit_code, 0) << yellow.out;
  nlohmann::json j = nlohmann::json::parse(yellow.out);
  EXPECT_NEAR(j["xy"][0].get<double>(), 0.444062, 1e-6);  // CIE 1931 spectral locus
  EXPECT_GT(j["lms"][0].get<double>(), 0.9);              // L fires
  EXPECT_GT(j["lms"][1].get<double>(), 0.7);              // M fires
  EXPECT_EQ(j["in_gamut"]["srgb"], false);                // spectral colours are outside
  std::vector<double> shown = j["displayable_srgb"];
  EXPECT_GT(shown[0], 0.8);  // shown as yellow: red and green, no blue
  EXPECT_GT(shown[1], 0.8);
  EXPECT_LT(shown[2], 0.1);

  Result daylight = run("color temperature 6504 --json");
  ASSERT_EQ(daylight.exit_code, 0) << daylight.out;
  nlohmann::json t = nlohmann::json::parse(daylight.out);
  EXPECT_NEAR(t["xy"][0].get<double>(), 0.3127, 0.01);
  EXPECT_EQ(t["in_gamut"]["srgb"], true);

  Result text = run("color temperature 1800");
  EXPECT_EQ(text.exit_code, 0);
  EXPECT_NE(text.out.find("in gamut"), std::string::npos);
  EXPECT_EQ(run("color temperature 0").exit_code, 2);
}

TEST(ColorCli, ImageConvertAndDiff) {
  fs::path dir = test::make_temp_dir("obscura-color-cli");
  std::string exr = (dir / "a.exr").string(), png = (dir / "a.png").string();
  ASSERT_EQ(run("render --width 32 --height 24 --spp 2 -q -o " + exr).exit_code, 0);
  Result convert = run("image convert " + exr + " " + png +
                       " --tonemap aces --exposure 1 --display display-p3 --bits 6 --dither bayer");
  ASSERT_EQ(convert.exit_code, 0) << convert.out;
  EXPECT_TRUE(fs::exists(png));

  Result same = run("image diff " + exr + " " + exr + " --json");
  ASSERT_EQ(same.exit_code, 0) << same.out;
  nlohmann::json j = nlohmann::json::parse(same.out);
  EXPECT_EQ(j["mse"].get<double>(), 0);
  EXPECT_TRUE(j["psnr_db"].is_null());  // identical: infinite PSNR

  std::string other = (dir / "b.png").string(), heat = (dir / "heat.png").string();
  ASSERT_EQ(run("image convert " + exr + " " + other).exit_code, 0);
  Result diff = run("image diff " + png + " " + other + " --heatmap " + heat);
  ASSERT_EQ(diff.exit_code, 0) << diff.out;
  EXPECT_NE(diff.out.find("PSNR"), std::string::npos);
  EXPECT_TRUE(fs::exists(heat));

  Result mismatch = run("image diff " + png + " " + exr);  // 8-bit vs float: same size, 3 ch
  EXPECT_EQ(mismatch.exit_code, 0);
  std::string small = (dir / "small.exr").string();
  ASSERT_EQ(run("render --width 8 --height 8 --spp 1 -q -o " + small).exit_code, 0);
  Result sizes = run("image diff " + exr + " " + small);
  EXPECT_EQ(sizes.exit_code, 1);
  EXPECT_NE(sizes.out.find("cannot compare"), std::string::npos) << sizes.out;

  // Never overwrite an input: converting a file onto itself, or a heat map onto a compared file.
  auto before = fs::last_write_time(png);
  Result onto_itself = run("image convert " + png + " " + png);
  EXPECT_EQ(onto_itself.exit_code, 1) << onto_itself.out;
  EXPECT_NE(onto_itself.out.find("refusing to overwrite an input"), std::string::npos)
      << onto_itself.out;
  Result heat_onto_input = run("image diff " + png + " " + other + " --heatmap " + other);
  EXPECT_EQ(heat_onto_input.exit_code, 1) << heat_onto_input.out;
  EXPECT_EQ(fs::last_write_time(png), before);
  fs::remove_all(dir);
}

TEST(ColorCli, NonFiniteInputPixelsAreReportedAndWrittenBlack) {
  // A PFM written by hand (Obscura's own writers never store NaN): 3×1 pixels, NaN, +Inf, grey.
  fs::path dir = test::make_temp_dir("obscura-color-cli-nan");
  std::string in = (dir / "bad.pfm").string(), out = (dir / "bad.png").string();
  {
    std::ofstream f(in, std::ios::binary);
    f << "PF\n3 1\n-1.0\n";
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    const float pixels[9] = {nan, 0.5f, 0.5f, inf, inf, inf, 0.5f, 0.5f, 0.5f};
    f.write(reinterpret_cast<const char*>(pixels), sizeof pixels);
  }
  Result r = run("image convert " + in + " " + out);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("1 pixel(s) with NaN and 1 with Inf"), std::string::npos) << r.out;
  Image png = read_image(out);
  EXPECT_EQ(png.data[0], 0.f);          // NaN → black
  EXPECT_EQ(png.data[3], 0.f);          // +Inf → black
  EXPECT_EQ(png.data[6], 188.f / 255);  // linear 0.5 → sRGB 188
  fs::remove_all(dir);
}

TEST(ColorCli, RenderTakesDisplayOptions) {
  fs::path dir = test::make_temp_dir("obscura-render-display");
  std::string out = (dir / "r.png").string();
  Result r =
      run("render --width 16 --height 16 --spp 1 -q --display rec2020-pq --tonemap hable "
          "--bits 10 --dither blue-noise -o " +
          out);
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_TRUE(fs::exists(out));
  EXPECT_EQ(run("render --bits 17 -o " + out).exit_code, 2);
  EXPECT_EQ(run("render --dither floyd -o " + out).exit_code, 2);
  // Without --bits, the HDR displays get 16 bits and the others 8: the PNG's bit depth (IHDR,
  // byte 24 of the file).
  for (const auto& [display, depth] :
       {std::pair{"rec2020-hlg", 16}, std::pair{"rec2020-pq", 16}, std::pair{"srgb", 8}}) {
    r = run("render --width 8 --height 8 --spp 1 -q --display " + std::string(display) + " -o " +
            out);
    ASSERT_EQ(r.exit_code, 0) << r.out;
    std::ifstream in(out, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    ASSERT_GT(bytes.size(), 24u);
    EXPECT_EQ(int(static_cast<unsigned char>(bytes[24])), depth) << display;
  }
  fs::remove_all(dir);
}

TEST(ColorCli, HugeValuesAreErrorsNotNaN) {
  // Finite input whose conversion overflows (1e308 through a matrix) is an error naming the
  // colour, not "-nan -nan -nan" reported as in gamut.
  Result huge = run("color convert --from srgb --to hsl 1e308 0 0");
  EXPECT_EQ(huge.exit_code, 1) << huge.out;
  EXPECT_NE(huge.out.find("too large to convert to hsl"), std::string::npos) << huge.out;
  EXPECT_EQ(huge.out.find("nan"), std::string::npos) << huge.out;
  Result hot = run("color temperature 1e308");
  EXPECT_EQ(hot.exit_code, 2) << hot.out;
  EXPECT_NE(hot.out.find("at most 1000000000"), std::string::npos) << hot.out;
  // sRGB white is a grey in HSL (CSS Color 4): hue 0, saturation 0, lightness 1.
  Result white = run("color convert --from srgb --to hsl 1 1 1");
  EXPECT_EQ(white.exit_code, 0) << white.out;
  EXPECT_EQ(white.out.rfind("0 0 1\n", 0), 0u) << white.out;
}

}  // namespace
}  // namespace obscura
