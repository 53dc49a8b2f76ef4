// The parsing half of the OBJ reader: one block of lines into statements with their numbers
// parsed, independent of every other block, so that blocks are parsed on several threads. What
// depends on the lines before (index resolution, vertex sharing, objects and materials) is left
// to obj_loader.cpp, which takes the blocks' statements in file order.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace obscura {

enum class ObjKeyword : uint8_t {
  kV,       // floats: x y z, or x y z r g b (count 3 or 6)
  kVt,      // floats: u v (as written; v defaults to 0)
  kVn,      // floats: x y z
  kF,       // corners [begin, begin + count), then perhaps a malformed index (error ≥ 0)
  kObject,  // "o": text
  kGroup,   // "g": text
  kUseMtl,  // text
  kMtlLib,  // text
  kError,   // a malformed statement: error
};

// An OBJ index as written (1-based, or negative: relative to the end).
inline constexpr int64_t kAbsentIndex = INT64_MIN;  // a corner without vt or vn

struct ObjCorner {
  int64_t v, vt, vn;
};

struct ObjStatement {
  ObjKeyword keyword;
  // kF with error ≥ 0: how many leading indices (v, vt, vn) of the corner after the complete
  // ones were read before the malformed one; they are checked before the error is reported.
  uint8_t partial = 0;
  int32_t error = -1;  // index into ObjStatements::errors
  uint32_t line;       // within the block, from 0
  uint32_t begin = 0;  // into floats, corners or texts
  uint32_t count = 0;
};

struct ObjStatements {
  std::vector<ObjStatement> statements;
  std::vector<float> floats;
  std::vector<ObjCorner> corners;
  std::vector<std::string> texts;   // names and file names, blanks trimmed
  std::vector<std::string> errors;  // messages, without the file and line
  uint32_t lines = 0;               // in the block
};

// Parses whole lines: keywords other than those above (comments, s, l, p, vp, curves, …) are
// skipped, as is a "f" line's corner list beyond its first malformed index.
void parse_obj_block(std::string_view text, ObjStatements& out);

}  // namespace obscura
