#include "obscura/camera/lens_prescription_file.h"

#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "obscura/math/error.h"

namespace obscura {

namespace {

constexpr const char* kColumns[] = {"radius_mm", "thickness_mm", "n_d", "aperture_diameter_mm",
                                    "V_d"};
constexpr size_t kRequiredColumns = 4;

std::vector<std::string_view> split_fields(std::string_view line) {
  std::vector<std::string_view> fields;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
    if (i > start) fields.push_back(line.substr(start, i - start));
  }
  return fields;
}

// A finite decimal number, all of `text`; the error names the field.
double parse_number(std::string_view text, const std::string& where, const std::string& field) {
  double value = 0;
  const char* begin = text.data();
  const char* end = begin + text.size();
  if (!text.empty() && *begin == '+') ++begin;  // from_chars refuses a leading '+'
  auto [stop, ec] = std::from_chars(begin, end, value);
  if (ec != std::errc() || stop != end || !std::isfinite(value))
    throw Error(where, field + ": expected a finite number; got '" + std::string(text) + "'");
  return value;
}

// key=value after the numeric columns.
void apply_keyed(LensSurface& s, std::string_view field, const std::string& where) {
  size_t equals = field.find('=');
  std::string key(field.substr(0, equals));
  std::string_view value = field.substr(equals + 1);
  if (key == "V_d") {
    s.abbe_number = parse_number(value, where, key);
  } else if (key == "conic") {
    s.conic = parse_number(value, where, key);
  } else if (key.size() >= 2 && key[0] == 'A') {
    int order = 0;
    auto [stop, ec] = std::from_chars(key.data() + 1, key.data() + key.size(), order);
    if (ec != std::errc() || stop != key.data() + key.size() || order < 4 || order > 16 ||
        order % 2 != 0)
      throw Error(where, "unknown aspheric coefficient '" + key + "'; expected A4, A6, … A16");
    s.aspheric[size_t(order / 2 - 2)] = parse_number(value, where, key);
  } else {
    throw Error(where, "unknown field '" + key + "'; expected V_d, conic or A4 … A16");
  }
}

LensSurface parse_row(const std::vector<std::string_view>& fields, const std::string& where) {
  size_t positional = 0;
  while (positional < fields.size() && fields[positional].find('=') == std::string_view::npos)
    ++positional;
  if (positional < kRequiredColumns || positional > std::size(kColumns))
    throw Error(where,
                "expected 4 numbers (radius_mm thickness_mm n_d aperture_diameter_mm), "
                "an optional V_d, then key=value fields; got " +
                    std::to_string(positional) + " number" + (positional == 1 ? "" : "s"));
  double values[std::size(kColumns)] = {};
  for (size_t i = 0; i < positional; ++i) values[i] = parse_number(fields[i], where, kColumns[i]);
  LensSurface s;
  s.radius_mm = values[0];
  s.thickness_mm = values[1];
  s.n_d = values[2];
  s.aperture_diameter_mm = values[3];
  s.abbe_number = values[4];
  for (size_t i = positional; i < fields.size(); ++i) {
    if (fields[i].find('=') == std::string_view::npos)
      throw Error(
          where, "'" + std::string(fields[i]) + "': bare numbers come before the key=value fields");
    apply_keyed(s, fields[i], where);
  }
  // The shared tables' convention: n_d 0 on a flat row is the stop, with air after it.
  if (s.n_d == 0) {
    if (s.radius_mm != 0)
      throw Error(where,
                  "n_d: 0 marks the aperture stop, which must be flat (radius_mm 0); got "
                  "radius " +
                      std::string(fields[0]));
    s.is_stop = true;
    s.n_d = 1;
  }
  try {
    validate(s);
  } catch (const Error& e) {
    throw Error(where, e.what());
  }
  return s;
}

}  // namespace

LensPrescription parse_lens_prescription(std::string_view text, const std::string& source,
                                         const std::string& name) {
  LensPrescription p;
  p.name = name;
  std::vector<int> lines;  // the file line of each surface
  int line_number = 0;
  while (!text.empty()) {
    size_t end = text.find('\n');
    std::string_view line = text.substr(0, end);
    text = end == std::string_view::npos ? std::string_view() : text.substr(end + 1);
    ++line_number;
    line = line.substr(0, line.find('#'));
    std::vector<std::string_view> fields = split_fields(line);
    if (fields.empty()) continue;
    const std::string where = source + ":" + std::to_string(line_number);
    p.surfaces.push_back(parse_row(fields, where));
    lines.push_back(line_number);
  }
  if (p.surfaces.empty())
    throw Error(source,
                "no surfaces: expected rows of radius_mm thickness_mm n_d "
                "aperture_diameter_mm");
  int stops = 0;
  for (size_t i = 0; i < p.surfaces.size(); ++i) {
    if (!p.surfaces[i].is_stop) continue;
    if (++stops > 1)
      throw Error(source + ":" + std::to_string(lines[i]),
                  "a second aperture stop (radius 0, n_d 0); a lens has one");
  }
  if (stops == 0) throw Error(source, "no aperture stop: one row must have radius_mm 0 and n_d 0");
  if (p.surfaces.back().n_d != 1)
    throw Error(source + ":" + std::to_string(lines.back()),
                "n_d: the last surface must have air (1) after it, towards the sensor");
  validate(p);  // anything left (no refracting surface) names the lens
  return p;
}

LensPrescription load_lens_prescription(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path, "cannot open the lens prescription file");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw Error(path, "cannot read the lens prescription file");
  return parse_lens_prescription(text.str(), path, std::filesystem::path(path).stem().string());
}

}  // namespace obscura
