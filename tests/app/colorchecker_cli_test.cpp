// A ColorChecker through the whole camera: the chart's 24 patches, rendered by the spectral path
// tracer under uniform D65 light, captured by the raw sensor, written as a DNG and developed by
// LibRaw (`dcraw_emu`, Debian's libraw-bin: an independent raw developer using the DNG's own
// ColorMatrix1 and AsShotNeutral) land within ΔE2000 3 of the chart's colours.
//
// The reference is computed here from the published spectra alone (BabelColor's average of 30
// ColorChecker Classic charts, data/color/README.md) × CIE D65 × the CIE 1931 2° observer at
// 1 nm: the colour each patch has under D65, in CIE L*a*b* relative to D65's white. The scene's
// reflectance per patch is that XYZ in linear sRGB (IEC 61966-2-1's matrix), clipped at 0 where
// the patch lies outside Rec.709 (cyan, whose red is −0.028: the clip alone moves it by ΔE00 2.0,
// which the test keeps in the budget rather than hides).
//
// Measurement: LibRaw develops linearly (-4) with the as-shot white balance (-w) to CIE XYZ
// (-o 5, D65-relative); each patch is the mean of its central 10 × 10 pixels (the middle half of
// a 20-pixel patch in each direction, clear of the demosaicing at the patch edges). A raw
// developer does not know the scene's absolute exposure, so one scale for the whole chart is
// fitted as chart-measuring tools do: the one that gives the six neutral patches their reference
// luminance in sum. ΔE00 is Sharma et al.'s (color/color_difference.h, tested on their pairs).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <iostream>
#include <map>
#include <numeric>
#include <sstream>
#include <vector>

#include "obscura/color/color_difference.h"
#include "obscura/io/image_io.h"
#include "run_command.h"
#include "test_paths.h"

namespace obscura {
namespace {

constexpr int kColumns = 6, kRows = 4, kPatchPixels = 20;

// A CSV of one header row and numeric rows, as data/color/ stores its tables.
std::vector<std::vector<double>> read_csv(const std::string& relative) {
  std::ifstream in(test::source_path(relative));
  EXPECT_TRUE(in.good()) << relative;
  std::vector<std::vector<double>> rows;
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::stringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');) row.push_back(std::stod(cell));
    rows.push_back(row);
  }
  return rows;
}

// The tables by wavelength (nm → row).
std::map<int, std::vector<double>> by_wavelength(const std::vector<std::vector<double>>& rows) {
  std::map<int, std::vector<double>> table;
  for (const auto& row : rows) table[int(std::lround(row[0]))] = row;
  return table;
}

struct Reference {
  std::vector<Vec3d> xyz;  // per patch under D65, Y = 1 for the perfect diffuser
  Vec3d white{};           // D65's XYZ, Y = 1
};

// CIE 15's colorimetry: X = Σ R(λ) S(λ) x̄(λ) / Σ S(λ) ȳ(λ) over 360–830 nm at 1 nm, the 10 nm
// reflectances interpolated linearly and held at their end values outside 380–730 nm.
Reference chart_under_d65() {
  const auto chart = read_csv("data/color/colorchecker_babelcolor_average_10nm.csv");
  auto cmf = by_wavelength(read_csv("data/color/cie1931_2deg_xyz_cmf_1nm.csv"));
  auto d65 = by_wavelength(read_csv("data/color/cie_illuminant_D65_1nm.csv"));
  EXPECT_EQ(chart.size(), 36u);
  Reference r;
  r.xyz.assign(24, Vec3d{});
  double norm = 0;
  for (int nm = 360; nm <= 830; ++nm) {
    const double s = d65.at(nm)[1];
    norm += s * cmf.at(nm)[2];
    for (int k = 0; k < 3; ++k) r.white[size_t(k)] += s * cmf.at(nm)[size_t(k) + 1];
    const double at = std::clamp((nm - 380) / 10.0, 0.0, 35.0);
    const size_t i = std::min(size_t(at), size_t(34));
    const double t = at - double(i);
    for (size_t p = 0; p < 24; ++p) {
      const double reflectance = chart[i][p + 1] * (1 - t) + chart[i + 1][p + 1] * t;
      for (int k = 0; k < 3; ++k)
        r.xyz[p][size_t(k)] += reflectance * s * cmf.at(nm)[size_t(k) + 1];
    }
  }
  for (auto& xyz : r.xyz)
    for (double& v : xyz) v /= norm;
  for (double& v : r.white) v /= norm;
  return r;
}

// CIE 1976 L*a*b* (CIE 15:2004, eq. 8.x) relative to `white`.
Vec3d lab(const Vec3d& xyz, const Vec3d& white) {
  auto f = [](double t) {
    constexpr double d = 6.0 / 29;
    return t > d * d * d ? std::cbrt(t) : t / (3 * d * d) + 4.0 / 29;
  };
  const double fx = f(xyz[0] / white[0]), fy = f(xyz[1] / white[1]), fz = f(xyz[2] / white[2]);
  return {116 * fy - 16, 500 * (fx - fy), 200 * (fy - fz)};
}

// IEC 61966-2-1 (sRGB), its 4-decimal matrices.
Vec3d linear_srgb(const Vec3d& xyz) {
  return {3.2406 * xyz[0] - 1.5372 * xyz[1] - 0.4986 * xyz[2],
          -0.9689 * xyz[0] + 1.8758 * xyz[1] + 0.0415 * xyz[2],
          0.0557 * xyz[0] - 0.2040 * xyz[1] + 1.0570 * xyz[2]};
}
Vec3d xyz_of_srgb(const Vec3d& rgb) {
  return {0.4124 * rgb[0] + 0.3576 * rgb[1] + 0.1805 * rgb[2],
          0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2],
          0.0193 * rgb[0] + 0.1192 * rgb[1] + 0.9505 * rgb[2]};
}

// The chart as a scene: a 6 × 4 grid of 1 m diffuse squares in the XY plane, seen square-on by
// an orthographic camera that the grid fills exactly, under uniform environment light of
// radiance 1000 cd/m² (D65 in spectral mode; an overcast sky). The patches are coplanar, so each
// reflects only the sky: its radiance is its reflectance times the sky's, noiseless in RGB and up
// to the wavelengths' noise in spectral mode.
std::string chart_scene(const std::vector<Vec3d>& reflectances) {
  std::ostringstream s;
  s << R"({"environment": {"color": 1000}, "materials": {)";
  for (size_t p = 0; p < reflectances.size(); ++p) {
    const Vec3d& c = reflectances[p];
    s << (p ? ", " : "") << "\"p" << p << R"(": {"type": "diffuse", "reflectance": [)" << c[0]
      << ", " << c[1] << ", " << c[2] << "]}";
  }
  s << R"(}, "objects": [)";
  for (size_t p = 0; p < reflectances.size(); ++p) {
    const double x = double(p % kColumns) - 2.5, y = 1.5 - double(p / kColumns);
    s << (p ? ", " : "") << R"({"shape": "rectangle", "material": "p)" << p
      << R"(", "transform": {"rotate_degrees": [90, 0, 0], "translate": [)" << x << ", " << y
      << ", 0]}}";
  }
  s << R"(], "cameras": [{"name": "chart", "type": "orthographic", "position": [0, 0, 5],
      "target": [0, 0, 0], "height": 4, "width": 6}]})";
  return s.str();
}

class ColorCheckerCli : public test::TempDirTest {};

TEST_F(ColorCheckerCli, LibRawDevelopsTheChartToItsPublishedColours) {
  if (test::run_shell("command -v dcraw_emu").exit_code != 0)
    GTEST_SKIP() << "LibRaw's dcraw_emu is not installed (scripts/setup: libraw-bin)";
  const Reference ref = chart_under_d65();
  std::vector<Vec3d> reflectances;
  for (const Vec3d& xyz : ref.xyz) {
    Vec3d rgb = linear_srgb(xyz);
    for (double& v : rgb) v = std::clamp(v, 0.0, 1.0);
    reflectances.push_back(rgb);
  }
  const std::string scene = path("chart.json"), dng = path("chart.dng");
  std::ofstream(scene) << chart_scene(reflectances);
  // 16-bit ADC and a 60 000 e⁻ well, 1/10 s: the white patch fills about half of it, so no
  // channel clips after LibRaw's white balance, shot noise averages out over a patch, and the
  // dark current (1 e⁻/s, not subtracted by a developer) stays far below the black patch's
  // signal. (At 80 s under a sky of 1 cd/m², the same exposure, its 80 e⁻ tint the dark patches
  // by up to ΔE00 3.5: a long exposure's dark signal, as in a real camera.)
  auto r = test::run_cli("render -q " + scene + " --spectral --spp 32 --width " +
                         std::to_string(kColumns * kPatchPixels) + " --height " +
                         std::to_string(kRows * kPatchPixels) +
                         " --shutter 0:0.1 --raw-sensor full_well_e=60000,adc_bits=16 -o " + dng);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  auto dev = test::run_shell("dcraw_emu -4 -o 5 -w '" + dng + "'");
  ASSERT_EQ(dev.exit_code, 0) << dev.output;
  const Image developed = read_image(dng + ".ppm");
  ASSERT_EQ(developed.width, kColumns * kPatchPixels);
  ASSERT_EQ(developed.height, kRows * kPatchPixels);
  ASSERT_EQ(developed.channels, 3);

  // Each patch's mean over its central half, in LibRaw's XYZ.
  std::vector<Vec3d> measured;
  for (int p = 0; p < 24; ++p) {
    const int x0 = (p % kColumns) * kPatchPixels, y0 = (p / kColumns) * kPatchPixels;
    const int margin = kPatchPixels / 4;
    Vec3d sum{};
    int n = 0;
    for (int y = y0 + margin; y < y0 + kPatchPixels - margin; ++y)
      for (int x = x0 + margin; x < x0 + kPatchPixels - margin; ++x, ++n)
        for (int c = 0; c < 3; ++c) sum[size_t(c)] += developed.at(x, y, c);
    for (double& v : sum) v /= n;
    measured.push_back(sum);
  }
  // One exposure scale: the six neutrals (patches 19–24) get their reference luminance in sum.
  double reference_grey = 0, measured_grey = 0;
  for (size_t p = 18; p < 24; ++p) {
    reference_grey += ref.xyz[p][1];
    measured_grey += measured[p][1];
  }
  ASSERT_GT(measured_grey, 0.1) << "the chart is exposed well above black";
  const double scale = reference_grey / measured_grey;

  double worst = 0, sum = 0, worst_chain = 0;
  size_t worst_patch = 0;
  for (size_t p = 0; p < 24; ++p) {
    Vec3d xyz = measured[p];
    for (double& v : xyz) v *= scale;
    const Vec3d got = lab(xyz, ref.white);
    const double de = delta_e_2000(got, lab(ref.xyz[p], ref.white));
    // What the chain itself moved: the developed colour against the colour the scene asked for.
    const double chain = delta_e_2000(got, lab(xyz_of_srgb(reflectances[p]), ref.white));
    EXPECT_LE(de, 3.0) << "patch " << p + 1 << ": developed L*a*b* " << got[0] << ", " << got[1]
                       << ", " << got[2];
    EXPECT_LE(chain, 1.5) << "patch " << p + 1;
    sum += de;
    worst_chain = std::max(worst_chain, chain);
    if (de > worst) worst = de, worst_patch = p + 1;
  }
  std::cout << "ColorChecker through the sensor, DNG and LibRaw: ΔE00 mean " << sum / 24 << ", max "
            << worst << " (patch " << worst_patch << "); the chain alone max " << worst_chain
            << "; exposure scale " << scale << "\n";
}

}  // namespace
}  // namespace obscura
