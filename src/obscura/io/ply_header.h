// The header of a PLY file (format, elements, properties), parsed and checked against the file's
// size before any element is read, so that a lying count is refused before it is allocated.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace obscura {

enum class PlyFormat { kAscii, kBinaryLittleEndian, kBinaryBigEndian };

enum class PlyType : uint8_t {
  kInt8,
  kUint8,
  kInt16,
  kUint16,
  kInt32,
  kUint32,
  kFloat32,
  kFloat64
};

// Bytes of one value in a binary file.
size_t ply_type_size(PlyType type);
// The largest value of an integer type (for scaling colours to [0, 1]); 1 for float types.
double ply_type_max(PlyType type);

struct PlyProperty {
  std::string name;
  PlyType type = PlyType::kFloat32;  // of the value, or of each list item
  bool is_list = false;
  PlyType count_type = PlyType::kUint8;  // of a list's length
};

struct PlyElement {
  std::string name;
  uint64_t count = 0;
  std::vector<PlyProperty> properties;

  // Where `name` is among the properties, or -1.
  int find(const std::string& property) const;
};

struct PlyHeader {
  PlyFormat format = PlyFormat::kAscii;
  std::vector<PlyElement> elements;
  size_t data_offset = 0;  // the first byte after "end_header\n"
  size_t lines = 0;        // the header's line count: ASCII data starts on line lines + 1
};

// Parses the header at the start of `bytes`, and checks that the declared elements can fit in the
// bytes after it (each binary value takes its size, each ASCII value at least two characters).
// Throws obscura::Error naming `name` and the header line or element otherwise.
PlyHeader parse_ply_header(std::span<const char> bytes, const std::string& name);

}  // namespace obscura
