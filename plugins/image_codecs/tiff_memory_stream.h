// libtiff reading from and writing to memory (TIFFClientOpenExt), with its errors collected per
// file instead of printed: the codecs never touch the output file itself.
#pragma once

#include <tiffio.h>

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace obscura::codecs {

struct TiffMemoryStream {
  std::span<const uint8_t> input;                // reading
  std::vector<unsigned char>* output = nullptr;  // writing
  uint64_t position = 0;
  std::string errors;  // libtiff's messages, "; "-separated
};

// Opens `stream` ("r" or "w"); nullptr when libtiff refuses (the reason in stream.errors).
TIFF* open_tiff_stream(TiffMemoryStream& stream, const char* mode, const std::string& name);

// The local time now as TIFF's DateTime tag writes it ("YYYY:MM:DD HH:MM:SS").
std::string now_as_tiff_date();

}  // namespace obscura::codecs
