#include "pfm_codec.h"

#include <bit>
#include <cctype>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>
#include <utility>

#include "obscura/math/error.h"

namespace obscura::codecs {

namespace {

class PfmDecoder final : public StoredImageDecoder {
 public:
  explicit PfmDecoder(EncodedBytes encoded) : encoded_(std::move(encoded)) {
    header_.format_name = "pnm";
    header_.format = SampleType::kFloat;
    const auto bytes = encoded_.bytes;
    header_.channels = bytes[1] == 'F' ? 3 : 1;
    header_.channel_names = header_.channels == 3 ? std::vector<std::string>{"R", "G", "B"}
                                                  : std::vector<std::string>{"Y"};
    position_ = 2;
    const long width = next_number("width"), height = next_number("height");
    if (width <= 0 || height <= 0 || width > INT32_MAX || height > INT32_MAX)
      fail("width and height must be positive");
    header_.width = int(width);
    header_.height = int(height);
    const std::string scale = next_token("scale");
    char* end = nullptr;
    const double s = std::strtod(scale.c_str(), &end);
    if (end != scale.c_str() + scale.size() || s == 0.0)
      fail("scale '" + scale + "' is not a non-zero number");
    little_endian_ = s < 0;
    if (position_ >= bytes.size() || !std::isspace(bytes[position_]))
      fail("no white space after the scale");
    ++position_;  // exactly one byte: the pixels may begin with any value
  }

 private:
  [[noreturn]] void fail(const std::string& why) const {
    throw Error(encoded_.source, "cannot read image as pnm (PFM): " + why);
  }

  // The next white-space separated token of the header (at most 32 characters).
  std::string next_token(const char* what) {
    const auto bytes = encoded_.bytes;
    while (position_ < bytes.size() && std::isspace(bytes[position_])) ++position_;
    std::string token;
    while (position_ < bytes.size() && !std::isspace(bytes[position_]) && token.size() < 32)
      token.push_back(char(bytes[position_++]));
    if (token.empty()) fail(std::string("the header ends before its ") + what);
    return token;
  }

  long next_number(const char* what) {
    const std::string token = next_token(what);
    for (char c : token)
      if (!std::isdigit(static_cast<unsigned char>(c)))
        fail(std::string(what) + " '" + token + "' is not a whole number");
    return token.size() > 10 ? -1 : std::strtol(token.c_str(), nullptr, 10);
  }

  void decode_stored(void* pixels) override {
    const size_t row = size_t(header_.width) * size_t(header_.channels) * 4;
    const size_t rows = size_t(header_.height);
    const auto bytes = encoded_.bytes;
    if (bytes.size() - position_ < row * rows) fail("the pixels are truncated");
    auto* out = static_cast<unsigned char*>(pixels);
    for (size_t y = 0; y < rows; ++y)  // the file's first row is the bottom one
      std::memcpy(out + (rows - 1 - y) * row, bytes.data() + position_ + y * row, row);
    if (little_endian_ != (std::endian::native == std::endian::little)) {
      for (size_t i = 0; i < row * rows; i += 4) {
        std::swap(out[i], out[i + 3]);
        std::swap(out[i + 1], out[i + 2]);
      }
    }
  }

  EncodedBytes encoded_;
  size_t position_ = 0;
  bool little_endian_ = true;
};

}  // namespace

std::unique_ptr<ImageDecoder> open_pfm(EncodedBytes encoded) {
  const auto bytes = encoded.bytes;
  if (bytes.size() < 3 || bytes[0] != 'P' || (bytes[1] != 'F' && bytes[1] != 'f')) return nullptr;
  return std::make_unique<PfmDecoder>(std::move(encoded));
}

}  // namespace obscura::codecs
