#include "obscura/io/mtl_reader.h"

#include <cmath>

#include "obscura/io/mesh_file.h"
#include "obscura/math/error.h"

namespace obscura {

namespace {

// Texture statement options and how many values each takes ("-o", "-s", "-t" take 1 to 3
// numbers; "-mm" two; the rest one).
int option_values(std::string_view option) {
  if (option == "-o" || option == "-s" || option == "-t") return 3;
  if (option == "-mm") return 2;
  return 1;  // -bm, -boost, -texres
}

class MtlParser {
 public:
  MtlParser(std::string_view text, const std::string& name, std::vector<std::string>& warnings)
      : lines_{text}, name_(name), warnings_(warnings) {}

  std::vector<MtlMaterial> parse() {
    std::string_view line;
    while (lines_.next(line)) {
      TextCursor c{line.data(), line.data() + line.size()};
      std::string_view keyword = c.token();
      if (keyword.empty() || keyword[0] == '#') continue;
      if (keyword == "newmtl") {
        finish_material();
        MtlMaterial m;
        m.name = std::string(c.rest());
        m.line = lines_.line_number;
        if (m.name.empty()) fail("'newmtl' without a name");
        materials_.push_back(std::move(m));
        continue;
      }
      if (keyword != "Ka" && keyword != "Kd" && keyword != "Ks" && keyword != "Ke" &&
          keyword != "Ns" && keyword != "d" && keyword != "map_Kd" && keyword != "map_Ke")
        continue;  // illum, Ni, Tf, bump maps, …: not part of the Phong mapping
      if (materials_.empty())
        fail(std::string("'").append(keyword).append("' before any 'newmtl'"));
      MtlMaterial& m = materials_.back();
      if (keyword == "Ka") m.ambient = color(c, keyword);
      if (keyword == "Kd") m.diffuse = color(c, keyword);
      if (keyword == "Ks") m.specular = color(c, keyword);
      if (keyword == "Ke") m.emission = color(c, keyword);
      if (keyword == "Ns") m.shininess = std::max(0.f, scalar(c, keyword));
      if (keyword == "d") m.dissolve = scalar(c, keyword);
      if (keyword == "map_Kd") m.diffuse_map = texture_path(c, keyword);
      if (keyword == "map_Ke") m.emission_map = texture_path(c, keyword);
    }
    finish_material();
    return std::move(materials_);
  }

 private:
  [[noreturn]] void fail(const std::string& message) const {
    throw Error(name_ + ":" + std::to_string(lines_.line_number), message);
  }

  float scalar(TextCursor& c, std::string_view keyword) {
    float v = 0;
    if (!c.number(v) || !std::isfinite(v))
      fail("expected a finite number after '" + std::string(keyword) + "'");
    return v;
  }

  // "Kd r g b", or "Kd r" for a grey (g and b default to r, as the MTL specification says).
  Rgb color(TextCursor& c, std::string_view keyword) {
    std::string_view k(keyword);
    if (c.p < c.end) {
      TextCursor peek = c;
      std::string_view first = peek.token();
      if (first == "spectral" || first == "xyz") {
        warnings_.push_back(name_ + ":" + std::to_string(lines_.line_number) + ": '" +
                            std::string(k) + " " + std::string(first) +
                            "' is not supported; the default colour is kept");
        return k == "Kd" ? Rgb(0.6f) : Rgb(0.f);
      }
    }
    // Appended, not "'" + string: GCC 12 warns falsely (-Wrestrict) about the latter here.
    std::string expected = std::string("expected '").append(k).append(" R G B'");
    float r = 0;
    if (!c.number(r)) fail(expected);
    float g = r, b = r;
    if (!c.at_end() && (!c.number(g) || !c.number(b))) fail(expected);
    if (!std::isfinite(r) || !std::isfinite(g) || !std::isfinite(b) || r < 0 || g < 0 || b < 0)
      fail(std::string("'").append(k).append("' must be finite and non-negative"));
    return {r, g, b};
  }

  std::string texture_path(TextCursor& c, std::string_view keyword) {
    while (true) {
      TextCursor save = c;
      std::string_view token = c.token();
      if (token.size() < 2 || token[0] != '-' || (token[1] >= '0' && token[1] <= '9')) {
        c = save;
        break;
      }
      // Numeric options take up to option_values() numbers; the others (-blendu on, -clamp
      // off, -imfchan r) one word.
      bool numeric = token == "-o" || token == "-s" || token == "-t" || token == "-mm" ||
                     token == "-bm" || token == "-boost" || token == "-texres";
      int taken = 0;
      float number = 0;
      if (numeric)
        while (taken < option_values(token) && c.number(number)) ++taken;
      else if (!c.token().empty())
        taken = 1;
      if (taken == 0)
        fail("option '" + std::string(token) + "' of '" + std::string(keyword) +
             "' without a value");
    }
    std::string_view path = c.rest();
    if (path.empty()) fail("'" + std::string(keyword) + "' without a file name");
    return std::string(path);
  }

  void finish_material() {
    if (materials_.empty()) return;
    const MtlMaterial& m = materials_.back();
    if (m.dissolve < 1)
      warnings_.push_back(name_ + ":" + std::to_string(m.line) + ": material '" + m.name +
                          "' is partly transparent (d " + std::to_string(m.dissolve) +
                          "), which is not rendered: it is drawn opaque");
  }

  LineReader lines_;
  const std::string& name_;
  std::vector<std::string>& warnings_;
  std::vector<MtlMaterial> materials_;
};

}  // namespace

std::vector<MtlMaterial> parse_mtl(std::string_view text, const std::string& name,
                                   std::vector<std::string>& warnings) {
  return MtlParser(text, name, warnings).parse();
}

}  // namespace obscura
