#include "obscura/io/obj_statements.h"

#include <charconv>
#include <cmath>
#include <cstring>

#include "obscura/io/mesh_file.h"

namespace obscura {

namespace {

class BlockParser {
 public:
  explicit BlockParser(ObjStatements& out) : out_(out) {}

  void line(std::string_view text, uint32_t number) {
    TextCursor c{text.data(), text.data() + text.size()};
    std::string_view keyword = c.token();
    if (keyword.empty() || keyword[0] == '#') return;
    line_ = number;
    if (keyword == "v") {
      vertex(c);
    } else if (keyword == "vt") {
      float uv[2] = {0, 0};
      if (!c.number(uv[0])) return error("expected 'vt U [V [W]]'");
      c.number(uv[1]);
      if (!finite(uv[0]) || !finite(uv[1])) return error("texture coordinate is not finite");
      add_floats(ObjKeyword::kVt, uv, 2);
    } else if (keyword == "vn") {
      float n[3];
      for (float& x : n)
        if (!c.number(x)) return error("expected 'vn X Y Z'");
      if (!finite(n[0]) || !finite(n[1]) || !finite(n[2])) return error("normal is not finite");
      add_floats(ObjKeyword::kVn, n, 3);
    } else if (keyword == "f") {
      face(c);
    } else if (keyword == "o") {
      add_text(ObjKeyword::kObject, c.rest());
    } else if (keyword == "g") {
      add_text(ObjKeyword::kGroup, c.rest());
    } else if (keyword == "usemtl") {
      add_text(ObjKeyword::kUseMtl, c.rest());
    } else if (keyword == "mtllib") {
      add_text(ObjKeyword::kMtlLib, c.rest());
    }
  }

 private:
  static bool finite(float x) { return std::isfinite(x); }

  ObjStatement& add(ObjKeyword keyword, size_t begin, size_t count) {
    return out_.statements.emplace_back(ObjStatement{
        .keyword = keyword, .line = line_, .begin = uint32_t(begin), .count = uint32_t(count)});
  }

  void error(std::string message) {
    add(ObjKeyword::kError, 0, 0).error = int32_t(out_.errors.size());
    out_.errors.push_back(std::move(message));
  }

  void add_floats(ObjKeyword keyword, const float* values, size_t count) {
    add(keyword, out_.floats.size(), count);
    out_.floats.insert(out_.floats.end(), values, values + count);
  }

  void add_text(ObjKeyword keyword, std::string_view text) {
    add(keyword, out_.texts.size(), 1);
    out_.texts.emplace_back(text);
  }

  void vertex(TextCursor& c) {
    float v[7];
    for (int i = 0; i < 3; ++i)
      if (!c.number(v[i])) return error("expected 'v X Y Z'");
    if (!finite(v[0]) || !finite(v[1]) || !finite(v[2]))
      return error("vertex position is not finite");
    int extra = 0;
    while (extra < 4 && c.number(v[3 + extra])) ++extra;
    // "v x y z r g b"; a lone fourth value is the rational weight w, and is dropped.
    add_floats(ObjKeyword::kV, v, extra == 3 ? 6 : 3);
  }

  // A 1-based or negative index, or false for text that is not one (empty included).
  static bool index(std::string_view text, int64_t& out) {
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
    return ec == std::errc() && end == text.data() + text.size() && !text.empty();
  }

  void face(TextCursor& c) {
    size_t begin = out_.corners.size();
    for (std::string_view token = c.token(); !token.empty(); token = c.token()) {
      size_t slash1 = token.find('/');
      std::string_view text[3] = {token.substr(0, slash1), {}, {}};
      bool present[3] = {true, false, false};
      if (slash1 != std::string_view::npos) {
        std::string_view rest = token.substr(slash1 + 1);
        size_t slash2 = rest.find('/');
        text[1] = rest.substr(0, slash2);
        present[1] = !text[1].empty();
        if (slash2 != std::string_view::npos) {
          text[2] = rest.substr(slash2 + 1);
          present[2] = !text[2].empty();
        }
      }
      ObjCorner corner{kAbsentIndex, kAbsentIndex, kAbsentIndex};
      int64_t* fields[3] = {&corner.v, &corner.vt, &corner.vn};
      for (int k = 0; k < 3; ++k) {
        if (!present[k] || index(text[k], *fields[k])) continue;
        // Reported after the indices before it are checked, as a reader going corner by
        // corner would.
        ObjStatement& s = add(ObjKeyword::kF, begin, out_.corners.size() - begin);
        out_.corners.push_back(corner);
        s.partial = uint8_t(k);
        s.error = int32_t(out_.errors.size());
        out_.errors.push_back("malformed face corner index '" + std::string(text[k].substr(0, 40)) +
                              "'");
        return;
      }
      out_.corners.push_back(corner);
    }
    add(ObjKeyword::kF, begin, out_.corners.size() - begin);
  }

  ObjStatements& out_;
  uint32_t line_ = 0;
};

}  // namespace

void parse_obj_block(std::string_view text, ObjStatements& out) {
  BlockParser parser(out);
  uint32_t number = 0;
  for (size_t offset = 0; offset < text.size(); ++number) {
    const char* start = text.data() + offset;
    const auto* newline = static_cast<const char*>(std::memchr(start, '\n', text.size() - offset));
    size_t length = newline ? size_t(newline - start) : text.size() - offset;
    std::string_view line(start, length);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    parser.line(line, number);
    offset += length + 1;
  }
  out.lines = number;
}

}  // namespace obscura
