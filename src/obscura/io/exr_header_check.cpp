#include "obscura/io/exr_header_check.h"

#include <bit>
#include <cstring>
#include <string>
#include <utility>

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

// The value size of the attribute types OpenEXR reads with a fixed layout (OpenEXR file layout,
// "Attribute Types"); 0 for the types whose size the value itself says.
size_t fixed_value_size(const std::string& type) {
  static const std::pair<const char*, size_t> kSizes[] = {{"box2i", 16},
                                                          {"box2f", 16},
                                                          {"chromaticities", 32},
                                                          {"compression", 1},
                                                          {"deepImageState", 1},
                                                          {"double", 8},
                                                          {"envmap", 1},
                                                          {"float", 4},
                                                          {"int", 4},
                                                          {"keycode", 28},
                                                          {"lineOrder", 1},
                                                          {"m33f", 36},
                                                          {"m33d", 72},
                                                          {"m44f", 64},
                                                          {"m44d", 128},
                                                          {"rational", 8},
                                                          {"tiledesc", 9},
                                                          {"timecode", 8},
                                                          {"v2i", 8},
                                                          {"v2f", 8},
                                                          {"v2d", 16},
                                                          {"v3i", 12},
                                                          {"v3f", 12},
                                                          {"v3d", 24}};
  for (const auto& [name, size] : kSizes)
    if (type == name) return size;
  return 0;
}

uint32_t read_u32(const ByteReader& read, uint64_t offset, bool& ok) {
  uint8_t b[4];
  if (!read(offset, 4, b)) {
    ok = false;
    return 0;
  }
  return uint32_t(b[0]) | uint32_t(b[1]) << 8 | uint32_t(b[2]) << 16 | uint32_t(b[3]) << 24;
}

// Checks that an attribute's value, `size` bytes at `offset`, is laid out as OpenEXR will read it.
// OpenEXR reads a fixed-layout value, a channel list or a preview image by its own layout, not by
// the declared size: a value that disagrees with its size leaves OpenEXR reading the rest of the
// header from the wrong place (a 13-byte box2i sent it on to read 1.7 GB from a 407-byte file,
// found by fuzz/image_fuzz.cpp), and a preview or string vector may declare sizes of its own.
void check_value(const ByteReader& read, uint64_t offset, uint64_t size, const std::string& name,
                 const std::string& type, const std::string& source) {
  auto refuse = [&](const std::string& why) {
    throw Error(source, "OpenEXR attribute '" + name + "' (" + type + "): " + why);
  };
  if (size_t fixed = fixed_value_size(type); fixed != 0) {
    if (size != fixed)
      refuse("declares " + std::to_string(size) + " bytes; a " + type + " holds " +
             std::to_string(fixed));
    return;
  }
  bool ok = true;
  uint64_t end = offset + size;
  if (type == "chlist") {
    // Channels: a name, then 16 bytes (type, pLinear, reserved, xSampling, ySampling); an empty
    // name ends the list, which must end exactly where the value does.
    std::string channel;
    for (uint64_t at = offset;;) {
      if (at >= end || !read_name(read, at, channel) || at > end)
        refuse("the channel list runs past its " + std::to_string(size) + " bytes");
      if (channel.empty()) {
        if (at != end)
          refuse("the channel list ends before its " + std::to_string(size) + " bytes");
        return;
      }
      at += 16;
    }
  }
  if (type == "preview") {
    uint64_t width = read_u32(read, offset, ok), height = read_u32(read, offset + 4, ok);
    // Compared without multiplying: two 32-bit sides can overflow 64 bits times 4.
    bool fills = ok && size >= 8 && (size - 8) % 4 == 0 &&
                 (width == 0 || height == 0
                      ? size == 8
                      : (size - 8) / 4 % width == 0 && (size - 8) / 4 / width == height);
    if (!fills)
      refuse("a preview image of " + std::to_string(width) + " × " + std::to_string(height) +
             " RGBA pixels does not fill its " + std::to_string(size) + " bytes");
    return;
  }
  if (type == "stringvector") {
    for (uint64_t at = offset; at < end;) {
      uint32_t length = read_u32(read, at, ok);
      if (!ok || end - at < 4 || length > end - at - 4)
        refuse("a string runs past the attribute's " + std::to_string(size) + " bytes");
      at += 4 + uint64_t(length);
    }
  }
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
    check_value(read, offset, uint64_t(size), name, type, source);
    // OpenEXR sizes its line buffers from the data window while opening the file, before any
    // pixel-count check can see the spec: a window millions of pixels wide must stop here.
    if (name == "dataWindow" && type == "box2i") {
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
