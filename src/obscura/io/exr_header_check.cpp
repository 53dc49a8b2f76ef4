#include "obscura/io/exr_header_check.h"

#include <bit>
#include <cstring>

#include "obscura/io/image_limits.h"
#include "obscura/math/error.h"

namespace obscura {

namespace {

constexpr uint32_t kMultipartFlag = 0x1000;  // version field bit 12 (OpenEXR file layout)
constexpr size_t kLongestName = 255;         // attribute names and types with "long names"

// A null-terminated string starting at `offset`; advances it past the terminator. False when the
// file ends first or the string is longer than any valid name.
bool read_name(const ByteReader& read, uint64_t& offset, std::string& name) {
  name.clear();
  uint8_t c = 0;
  while (name.size() <= kLongestName) {
    if (!read(offset++, 1, &c)) return false;
    if (c == 0) return true;
    name.push_back(char(c));
  }
  return false;
}

}  // namespace

bool is_exr_magic(const uint8_t magic[4]) {
  return magic[0] == 0x76 && magic[1] == 0x2f && magic[2] == 0x31 && magic[3] == 0x01;
}

void check_exr_header(const ByteReader& read, uint64_t total_size, const std::string& source) {
  uint8_t version[4];
  if (!read(4, 4, version)) throw Error(source, "OpenEXR file ends inside its version field");
  bool multipart = (uint32_t(version[1]) << 8 & kMultipartFlag) != 0;
  uint64_t offset = 8;
  std::string name, type;
  // Single part: one header ended by an empty name. Multipart: headers, each ended by an empty
  // name, and an empty header ending the list.
  for (;;) {
    if (!read_name(read, offset, name))
      throw Error(source, "OpenEXR header attribute name runs past the end of the file");
    if (name.empty()) {
      if (!multipart) return;
      // End of one part's header; an immediately following empty name ends the list.
      uint8_t next = 0;
      if (!read(offset, 1, &next)) throw Error(source, "OpenEXR multipart header is truncated");
      if (next == 0) return;
      continue;
    }
    if (!read_name(read, offset, type))
      throw Error(source, "OpenEXR attribute '" + name + "' has no type before the end");
    uint8_t size_bytes[4];
    if (!read(offset, 4, size_bytes))
      throw Error(source, "OpenEXR attribute '" + name + "' is truncated");
    offset += 4;
    int32_t size = 0;
    static_assert(std::endian::native == std::endian::little, "OpenEXR stores little-endian");
    std::memcpy(&size, size_bytes, 4);
    if (size < 0 || uint64_t(size) > total_size - offset)
      throw Error(source, "OpenEXR attribute '" + name + "' declares " + std::to_string(size) +
                              " bytes, more than the " + std::to_string(total_size - offset) +
                              " left in the file");
    // OpenEXR sizes its line buffers from the data window while opening the file, before any
    // pixel-count check can see the spec: a window millions of pixels wide must stop here.
    if (name == "dataWindow" && type == "box2i" && size == 16) {
      uint8_t box_bytes[16];
      int32_t box[4];  // xMin, yMin, xMax, yMax
      if (!read(offset, 16, box_bytes)) throw Error(source, "OpenEXR dataWindow is truncated");
      std::memcpy(box, box_bytes, 16);
      int64_t width = int64_t(box[2]) - box[0] + 1, height = int64_t(box[3]) - box[1] + 1;
      if (width <= 0 || height <= 0 || uint64_t(width) > kMaxImageRowValues / 4)
        throw Error(source, "OpenEXR dataWindow is " + std::to_string(width) + " × " +
                                std::to_string(height) + " pixels; rows of 1 to " +
                                std::to_string(kMaxImageRowValues / 4) + " pixels are read");
    }
    offset += uint64_t(size);
  }
}

}  // namespace obscura
