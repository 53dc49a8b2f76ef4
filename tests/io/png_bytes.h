// PNG files written byte by byte from the PNG specification (ISO/IEC 15948), for tests that need
// exact control over what a file holds: chunk framing with its CRC, and an uncompressed image
// carried in "stored" deflate blocks (RFC 1950/1951), so no encoder stands between the test and
// the bytes.
#pragma once

#include <cstdint>
#include <vector>

namespace obscura::test {

// CRC-32 as PNG specifies it (ISO 3309, polynomial 0xEDB88320, reflected), bit by bit.
inline uint32_t png_crc(const std::vector<uint8_t>& bytes, size_t begin, size_t end) {
  uint32_t crc = 0xFFFFFFFFu;
  for (size_t i = begin; i < end; ++i) {
    crc ^= bytes[i];
    for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
  }
  return crc ^ 0xFFFFFFFFu;
}

inline void put_u32(std::vector<uint8_t>& out, uint32_t v) {  // big-endian, as PNG stores
  const uint8_t bytes[4] = {uint8_t(v >> 24), uint8_t(v >> 16), uint8_t(v >> 8), uint8_t(v)};
  out.insert(out.end(), bytes, bytes + 4);
}

inline void put_chunk(std::vector<uint8_t>& out, const char* type,
                      const std::vector<uint8_t>& data) {
  put_u32(out, uint32_t(data.size()));
  size_t start = out.size();
  out.insert(out.end(), type, type + 4);
  out.insert(out.end(), data.begin(), data.end());
  put_u32(out, png_crc(out, start, out.size()));
}

// An 8-bit RGBA PNG (colour type 6: straight, unassociated alpha) of width × height holding
// `rgba` row by row, each row with filter type 0, in one stored deflate block (< 65536 bytes).
inline std::vector<uint8_t> rgba8_png(uint32_t width, uint32_t height,
                                      const std::vector<uint8_t>& rgba) {
  std::vector<uint8_t> raw;
  for (uint32_t y = 0; y < height; ++y) {
    raw.push_back(0);
    raw.insert(raw.end(), rgba.begin() + y * width * 4, rgba.begin() + (y + 1) * width * 4);
  }
  std::vector<uint8_t> zlib = {0x78, 0x01, 0x01};  // CMF/FLG; final stored block
  uint16_t len = uint16_t(raw.size());
  zlib.insert(zlib.end(), {uint8_t(len), uint8_t(len >> 8), uint8_t(~len), uint8_t(~len >> 8)});
  zlib.insert(zlib.end(), raw.begin(), raw.end());
  uint32_t a = 1, b = 0;  // Adler-32
  for (uint8_t v : raw) a = (a + v) % 65521, b = (b + a) % 65521;
  put_u32(zlib, b << 16 | a);
  std::vector<uint8_t> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  std::vector<uint8_t> ihdr;
  put_u32(ihdr, width);
  put_u32(ihdr, height);
  ihdr.insert(ihdr.end(), {8, 6, 0, 0, 0});  // depth 8, RGBA, deflate, filter 0, no interlace
  put_chunk(png, "IHDR", ihdr);
  put_chunk(png, "IDAT", zlib);
  put_chunk(png, "IEND", {});
  return png;
}

}  // namespace obscura::test
