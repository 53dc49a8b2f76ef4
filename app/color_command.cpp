#include "color_command.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "obscura/color/color_space.h"
#include "obscura/color/gamut.h"
#include "obscura/color/spectral.h"
#include "obscura/math/error.h"
#include "usage_error.h"

namespace obscura::app {

namespace {

std::string number(double v) {
  char buffer[32];
  // Round-off residue (a grey's 1e-16 OKLab a, b) prints as 0.
  std::snprintf(buffer, sizeof buffer, "%.10g", std::abs(v) < 1e-14 ? 0.0 : v);
  return buffer;
}

std::string list(const std::vector<double>& v, const char* separator = " ") {
  std::string s;
  for (size_t i = 0; i < v.size(); ++i) s += (i ? separator : "") + number(v[i]);
  return s;
}

std::string json_list(const std::vector<double>& v) {
  return "[" + list(v, ", ") + "]";
}
std::string json_bool(bool b) {
  return b ? "true" : "false";
}

// The RGB space whose gamut a result is judged against: the target itself when it is RGB,
// otherwise sRGB (what most screens show).
const ColorSpaceInfo& gamut_space(const ColorSpaceInfo& target) {
  return target.model == ColorModel::kRgb ? target : color_space("srgb");
}

// ---- convert ----------------------------------------------------------------------------------

struct ConvertOptions {
  std::string from, to;
  std::vector<std::string> values;
  bool json = false;
};

std::vector<double> parse_values(const std::vector<std::string>& words, const ColorSpaceInfo& from,
                                 const std::string& where, bool usage) {
  auto fail = [&](const std::string& what) -> std::vector<double> {
    if (usage) throw UsageError(what);
    throw Error(where, what);
  };
  if (int(words.size()) != from.components)
    return fail("'" + from.name + "' takes " + std::to_string(from.components) + " values; got " +
                std::to_string(words.size()));
  std::vector<double> values;
  for (const std::string& w : words) {
    size_t used = 0;
    double v = 0;
    try {
      v = std::stod(w, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != w.size()) return fail("'" + w + "' is not a number");
    if (!std::isfinite(v)) return fail("values must be finite; got '" + w + "'");
    values.push_back(v);
  }
  return values;
}

void print_conversion(const ConvertOptions& o, const std::vector<double>& in, bool single) {
  const ColorSpaceInfo& target = color_space(o.to);
  Vec3d xyz = xyz_d65_from(color_space(o.from), in);
  std::vector<double> out = from_xyz_d65(target, xyz);
  // Finite input can still overflow on the way (1e308 through a matrix, a cube or a power).
  auto finite = [](double v) { return std::isfinite(v); };
  if (!std::all_of(xyz.begin(), xyz.end(), finite) || !std::all_of(out.begin(), out.end(), finite))
    throw Error("color convert", "the colour " + list(in) + " in " + o.from +
                                     " is too large to convert to " + o.to +
                                     " (the result overflows a double)");
  const ColorSpaceInfo& gamut = gamut_space(target);
  bool inside = in_gamut(gamut.primaries, xyz);
  if (o.json) {
    std::printf(
        "{\"from\": \"%s\", \"to\": \"%s\", \"input\": %s, \"output\": %s, "
        "\"gamut\": \"%s\", \"in_gamut\": %s}\n",
        o.from.c_str(), o.to.c_str(), json_list(in).c_str(), json_list(out).c_str(),
        gamut.name.c_str(), json_bool(inside).c_str());
  } else {
    std::printf("%s\n", list(out).c_str());
    if (single) std::printf("in gamut of %s: %s\n", gamut.name.c_str(), inside ? "yes" : "no");
  }
}

void run_convert(const ConvertOptions& o) {
  const ColorSpaceInfo* from = nullptr;
  try {
    from = &color_space(o.from);
    color_space(o.to);
  } catch (const Error& e) {
    throw UsageError(e.what());
  }
  if (!o.values.empty()) {
    print_conversion(o, parse_values(o.values, *from, "", true), true);
    return;
  }
  // Batch: one colour per line of standard input, one result per line.
  std::string line;
  for (int line_number = 1; std::getline(std::cin, line); ++line_number) {
    std::istringstream words_in(line);
    std::vector<std::string> words;
    for (std::string w; words_in >> w;) words.push_back(w);
    if (words.empty()) continue;
    print_conversion(o, parse_values(words, *from, "stdin:" + std::to_string(line_number), false),
                     false);
    std::fflush(stdout);
  }
}

// ---- wavelength and temperature ---------------------------------------------------------------

// A displayable version of a colour too bright or saturated to show: CSS chroma compression in
// sRGB (constant OKLab lightness and hue), then scaled so that its brightest channel is 1, so
// that every colour is shown at full brightness.
std::vector<double> displayable_srgb(const Vec3d& xyz) {
  const ColorSpaceInfo& srgb = color_space("srgb");
  const ColorSpaceInfo& linear = color_space("srgb-linear");
  std::vector<double> rgb = from_xyz_d65(linear, xyz);
  double peak = std::max({rgb[0], rgb[1], rgb[2], 1e-30});
  std::vector<double> e = from_xyz_d65(srgb, {xyz[0] / peak, xyz[1] / peak, xyz[2] / peak});
  Vec3d mapped = gamut_map_css({e[0], e[1], e[2]}, srgb);
  Vec3d mapped_linear;
  for (int k = 0; k < 3; ++k) mapped_linear[k] = decode(TransferFunction::kSrgb, mapped[k]);
  double top = std::max({mapped_linear[0], mapped_linear[1], mapped_linear[2], 1e-30});
  std::vector<double> out(3);
  for (int k = 0; k < 3; ++k) out[k] = encode(TransferFunction::kSrgb, mapped_linear[k] / top);
  return out;
}

std::string hex(const std::vector<double>& encoded) {
  char buffer[8];
  auto byte = [](double v) { return int(std::floor(std::clamp(v, 0.0, 1.0) * 255 + 0.5)); };
  std::snprintf(buffer, sizeof buffer, "#%02x%02x%02x", byte(encoded[0]), byte(encoded[1]),
                byte(encoded[2]));
  return buffer;
}

void print_spectral(const std::string& what, double value, const Vec3d& xyz, const Vec3d* lms,
                    bool json) {
  Chromaticity xy = chromaticity_of(xyz);
  std::vector<double> linear = from_xyz_d65(color_space("srgb-linear"), xyz);
  std::vector<double> p3 = from_xyz_d65(color_space("display-p3-linear"), xyz);
  std::vector<double> r2020 = from_xyz_d65(color_space("rec2020-linear"), xyz);
  // Brightness aside (a monochromatic light can be as bright as you like), is the colour
  // inside each gamut?
  auto chroma_inside = [&](const RgbPrimaries& p) { return in_gamut(p, xyz, 1e-9, true); };
  bool in_srgb = chroma_inside(primaries::kRec709);
  bool in_p3 = chroma_inside(primaries::kDisplayP3);
  bool in_2020 = chroma_inside(primaries::kRec2020);
  std::vector<double> shown = displayable_srgb(xyz);
  if (json) {
    std::printf("{\"%s\": %s, \"xyz\": %s, \"xy\": %s, ", what.c_str(), number(value).c_str(),
                json_list({xyz[0], xyz[1], xyz[2]}).c_str(), json_list({xy.x, xy.y}).c_str());
    if (lms) std::printf("\"lms\": %s, ", json_list({(*lms)[0], (*lms)[1], (*lms)[2]}).c_str());
    std::printf(
        "\"srgb_linear\": %s, \"in_gamut\": {\"srgb\": %s, \"display-p3\": %s, "
        "\"rec2020\": %s}, \"displayable_srgb\": %s, \"hex\": \"%s\"}\n",
        json_list(linear).c_str(), json_bool(in_srgb).c_str(), json_bool(in_p3).c_str(),
        json_bool(in_2020).c_str(), json_list(shown).c_str(), hex(shown).c_str());
    return;
  }
  std::printf("XYZ            %s\n", list({xyz[0], xyz[1], xyz[2]}).c_str());
  std::printf("xy             %s\n", list({xy.x, xy.y}).c_str());
  if (lms) std::printf("LMS (cones)    %s\n", list({(*lms)[0], (*lms)[1], (*lms)[2]}).c_str());
  std::printf("linear sRGB    %s\n", list(linear).c_str());
  std::printf("linear P3      %s\n", list(p3).c_str());
  std::printf("linear Rec2020 %s\n", list(r2020).c_str());
  std::printf("in gamut       srgb: %s, display-p3: %s, rec2020: %s\n", in_srgb ? "yes" : "no",
              in_p3 ? "yes" : "no", in_2020 ? "yes" : "no");
  std::printf("shown as sRGB  %s (%s)%s\n", list(shown).c_str(), hex(shown).c_str(),
              in_srgb ? "" : ", chroma reduced to fit");
}

double parse_positive(const std::string& word, const std::string& what, double max) {
  size_t used = 0;
  double v = 0;
  try {
    v = std::stod(word, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != word.size() || !std::isfinite(v) || v <= 0 || v > max)
    throw UsageError(what + " must be a positive number of at most " + number(max) + "; got '" +
                     word + "'");
  return v;
}

}  // namespace

void add_color_command(CLI::App& app) {
  CLI::App* color = app.add_subcommand("color", "Colour conversions and spectral colours");
  color->require_subcommand(1);

  auto convert = std::make_shared<ConvertOptions>();
  CLI::App* c = color->add_subcommand(
      "convert", "Convert a colour between spaces; with no values, one colour per stdin line");
  c->add_option("--from", convert->from, "Source space (see `obscura color spaces`)")->required();
  c->add_option("--to", convert->to, "Target space")->required();
  c->add_option("values", convert->values, "The colour's components (3, or 4 for cmyk)")
      ->allow_extra_args();
  c->add_flag("--json", convert->json, "Machine-readable output, one JSON object per colour");
  c->callback([convert] { run_convert(*convert); });

  auto wavelength = std::make_shared<std::pair<std::string, bool>>();
  CLI::App* w = color->add_subcommand("wavelength", "The colour of monochromatic light");
  w->add_option("nm", wavelength->first, "Wavelength in nanometres")->required();
  w->add_flag("--json", wavelength->second, "Machine-readable output");
  w->callback([wavelength] {
    double nm = parse_positive(wavelength->first, "the wavelength", 1e9);
    Vec3d xyz = cmf_xyz(nm), lms = cone_lms(nm);
    if (xyz[0] + xyz[1] + xyz[2] == 0)
      throw Error("wavelength", number(nm) +
                                    " nm is outside the CIE 1931 observer's range "
                                    "(360-830 nm): the eye does not see it");
    print_spectral("wavelength_nm", nm, xyz, &lms, wavelength->second);
  });

  auto temperature = std::make_shared<std::pair<std::string, bool>>();
  CLI::App* t = color->add_subcommand("temperature", "The colour of a blackbody (Planck)");
  t->add_option("kelvin", temperature->first, "Temperature in kelvin")->required();
  t->add_flag("--json", temperature->second, "Machine-readable output");
  t->callback([temperature] {
    double kelvin = parse_positive(temperature->first, "the temperature", 1e9);
    print_spectral("kelvin", kelvin, blackbody_xyz(kelvin), nullptr, temperature->second);
  });

  CLI::App* s = color->add_subcommand("spaces", "List the colour spaces `convert` knows");
  s->callback([] {
    for (const ColorSpaceInfo& space : color_spaces())
      std::printf("%-24s %s\n", space.name.c_str(), space.description.c_str());
  });
}

}  // namespace obscura::app
