#include "png_codec.h"

#include <png.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <string>
#include <utility>

#include "encode_attributes.h"
#include "obscura/math/error.h"
#include "sample_conversion.h"

namespace obscura::codecs {

namespace {

// libpng reports errors through a callback that must not return: it records the message and
// jumps back to the setjmp of the call that failed, which then throws obscura::Error. (No C++
// object with a destructor may live between that setjmp and libpng.)
struct PngState {
  std::span<const uint8_t> bytes;  // reading
  size_t position = 0;
  std::vector<unsigned char>* output = nullptr;  // writing
  char message[256] = "";
};

void on_error(png_structp png, png_const_charp message) {
  auto* state = static_cast<PngState*>(png_get_error_ptr(png));
  std::snprintf(state->message, sizeof state->message, "%s", message);
  png_longjmp(png, 1);
}

void on_warning(png_structp, png_const_charp) {}

void read_bytes(png_structp png, png_bytep out, png_size_t size) {
  auto* state = static_cast<PngState*>(png_get_io_ptr(png));
  if (size > state->bytes.size() - state->position) png_error(png, "the file is truncated");
  std::memcpy(out, state->bytes.data() + state->position, size);
  state->position += size;
}

void write_bytes(png_structp png, png_bytep data, png_size_t size) {
  auto* state = static_cast<PngState*>(png_get_io_ptr(png));
  state->output->insert(state->output->end(), data, data + size);
}

void flush_nothing(png_structp) {}

struct PngReadHandles {
  png_structp png = nullptr;
  png_infop info = nullptr;
  ~PngReadHandles() { png_destroy_read_struct(&png, &info, nullptr); }
};

class PngDecoder final : public StoredImageDecoder {
 public:
  explicit PngDecoder(EncodedBytes encoded) : encoded_(std::move(encoded)) {
    state_.bytes = encoded_.bytes;
    handles_.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &state_, on_error, on_warning);
    if (handles_.png) handles_.info = png_create_info_struct(handles_.png);
    png_ = handles_.png;
    info_ = handles_.info;
    if (!png_ || !info_) throw Error(encoded_.source, "cannot read image as png: out of memory");
    png_set_read_fn(png_, &state_, read_bytes);
    check_chunk_lengths();
    if (!read_info()) fail();
    header_.format_name = "png";
    header_.channel_names = default_channel_names(header_.channels);
  }

 private:
  [[noreturn]] void fail() const {
    throw Error(encoded_.source, std::string("cannot read image as png: ") + state_.message);
  }

  // libpng allocates a chunk's declared length before reading it, whatever its chunk size limit
  // says (Debian's 1.6.39: a 271-byte file declaring a 1.9 GB tEXt chunk got 1.9 GB; found by
  // fuzz/image_fuzz.cpp). So every chunk up to the pixels must fit in the file, and none but the
  // pixels may exceed 8 MiB.
  void check_chunk_lengths() const {
    const auto bytes = encoded_.bytes;
    size_t at = 8;  // after the signature
    while (bytes.size() >= 8 && at <= bytes.size() - 8) {
      const uint32_t length = uint32_t(bytes[at]) << 24 | uint32_t(bytes[at + 1]) << 16 |
                              uint32_t(bytes[at + 2]) << 8 | uint32_t(bytes[at + 3]);
      const std::string type(reinterpret_cast<const char*>(bytes.data() + at + 4), 4);
      if (type == "IDAT") return;
      if (length > (8u << 20) || length > bytes.size() - at - 8)
        throw Error(encoded_.source, "cannot read image as png: the chunk at byte " +
                                         std::to_string(at) + " declares " +
                                         std::to_string(length) + " bytes, more than " +
                                         (length > (8u << 20) ? "8 MiB" : "the file holds"));
      at += size_t(length) + 12;  // length, type, data, CRC
    }
  }

  bool read_info() {
    if (setjmp(png_jmpbuf(png_))) return false;
    // The header's size is checked by the caller before anything is decoded; libpng's own
    // limit only keeps absurd ones out of its row allocations.
    png_set_user_limits(png_, 1u << 24, 1u << 24);
    // Ancillary chunks (text, ICC profiles) of at most 8 MiB and 1000 in number (see also
    // check_chunk_lengths).
    png_set_chunk_malloc_max(png_, 8u << 20);
    png_set_chunk_cache_max(png_, 1000);
    png_read_info(png_, info_);
    png_uint_32 width = 0, height = 0;
    int bit_depth = 0, color_type = 0;
    png_get_IHDR(png_, info_, &width, &height, &bit_depth, &color_type, nullptr, nullptr, nullptr);
    if (color_type == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(png_);
    if (color_type == PNG_COLOR_TYPE_GRAY && bit_depth < 8) png_set_expand_gray_1_2_4_to_8(png_);
    if (png_get_valid(png_, info_, PNG_INFO_tRNS)) png_set_tRNS_to_alpha(png_);
    if (bit_depth == 16) png_set_swap(png_);  // to this machine's byte order
    png_set_interlace_handling(png_);
    png_read_update_info(png_, info_);
    header_.width = int(width);
    header_.height = int(height);
    header_.channels = png_get_channels(png_, info_);
    header_.format =
        png_get_bit_depth(png_, info_) == 16 ? SampleType::kUint16 : SampleType::kUint8;
    png_textp text = nullptr;
    int count = png_get_text(png_, info_, &text, nullptr);
    for (int i = 0; i < count; ++i) {
      std::string key = text[i].key;
      header_.text_attributes.emplace_back(
          key == "Description" ? "ImageDescription" : key,
          std::string(text[i].text,
                      text[i].text_length ? text[i].text_length : text[i].itxt_length));
    }
    if (png_get_valid(png_, info_, PNG_INFO_sRGB) && !header_.has_attribute("oiio:ColorSpace"))
      header_.text_attributes.emplace_back("oiio:ColorSpace", "sRGB");
    return true;
  }

  void decode_stored(void* pixels) override {
    const size_t row =
        size_t(header_.width) * size_t(header_.channels) * sample_size(header_.format);
    rows_.resize(size_t(header_.height));
    for (size_t y = 0; y < rows_.size(); ++y) rows_[y] = static_cast<png_bytep>(pixels) + y * row;
    if (!read_rows()) fail();
  }

  bool read_rows() {
    if (setjmp(png_jmpbuf(png_))) return false;
    png_read_image(png_, rows_.data());
    return true;
  }

  EncodedBytes encoded_;
  PngState state_;
  PngReadHandles handles_;  // destroyed even when the constructor throws
  png_structp png_ = nullptr;
  png_infop info_ = nullptr;
  std::vector<png_bytep> rows_;
};

struct PngWriter {
  png_structp png = nullptr;
  png_infop info = nullptr;
  ~PngWriter() { png_destroy_write_struct(&png, &info); }
};

// Writes everything prepared in `text` and `rows`; false (and state.message) on failure.
bool write_png(PngWriter& w, const EncodeRequest& request, int bit_depth,
               std::vector<png_text>& text, std::vector<png_bytep>& rows) {
  if (setjmp(png_jmpbuf(w.png))) return false;
  static constexpr int kColorTypes[] = {PNG_COLOR_TYPE_GRAY, PNG_COLOR_TYPE_GRAY_ALPHA,
                                        PNG_COLOR_TYPE_RGB, PNG_COLOR_TYPE_RGB_ALPHA};
  png_set_IHDR(w.png, w.info, png_uint_32(request.width), png_uint_32(request.height), bit_depth,
               kColorTypes[request.channels - 1], PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
               PNG_FILTER_TYPE_DEFAULT);
  const std::string* space = text_attribute(request, "oiio:ColorSpace");
  if (space && *space == "sRGB")  // sRGB, with gAMA and cHRM for readers that know only those
    png_set_sRGB_gAMA_and_cHRM(w.png, w.info, PNG_sRGB_INTENT_PERCEPTUAL);
  // Wide-gamut and HDR encodings declare themselves in a cICP chunk (PNG third edition; ITU-T
  // H.273 code points: primaries, transfer, matrix 0 for RGB, full range), which libpng 1.6.39
  // writes as a chunk it does not interpret, before the image data where it must stand.
  png_byte cicp[4] = {0, 0, 0, 1};
  if (space && *space == "Display P3") cicp[0] = 12, cicp[1] = 13;  // P3-D65, sRGB's curve
  if (space && *space == "Rec2100-PQ") cicp[0] = 9, cicp[1] = 16;   // BT.2020, SMPTE ST 2084
  if (space && *space == "Rec2100-HLG") cicp[0] = 9, cicp[1] = 18;  // BT.2020, BT.2100 HLG
  png_unknown_chunk chunk{};
  if (cicp[0] != 0) {
    std::memcpy(chunk.name, "cICP", 5);
    chunk.data = cicp;
    chunk.size = sizeof cicp;
    chunk.location = PNG_HAVE_IHDR;
    static const png_byte kName[] = "cICP";
    png_set_keep_unknown_chunks(w.png, PNG_HANDLE_CHUNK_ALWAYS, kName, 1);
    png_set_unknown_chunks(w.png, w.info, &chunk, 1);
  }
  if (!text.empty()) png_set_text(w.png, w.info, text.data(), int(text.size()));
  // "png:compression" (an int, 0-9): zlib's level, for a caller that wants speed over size (the
  // live view's frames); 1 takes the one cheap row filter instead of trying all, and 0 (stored,
  // nothing to compress for) none.
  for (const HeaderAttribute& attribute : request.attributes)
    if (const int* level = std::get_if<int>(&attribute.value);
        level && attribute.name == "png:compression") {
      png_set_compression_level(w.png, std::clamp(*level, 0, 9));
      if (*level <= 0)
        png_set_filter(w.png, PNG_FILTER_TYPE_BASE, PNG_FILTER_NONE);
      else if (*level == 1)
        png_set_filter(w.png, PNG_FILTER_TYPE_BASE, PNG_FILTER_SUB);
    }
  png_write_info(w.png, w.info);
  if (bit_depth == 16) png_set_swap(w.png);
  png_write_image(w.png, rows.data());
  png_write_end(w.png, w.info);
  return true;
}

}  // namespace

std::unique_ptr<ImageDecoder> open_png(EncodedBytes encoded) {
  return std::make_unique<PngDecoder>(std::move(encoded));
}

std::vector<unsigned char> encode_png(const EncodeRequest& request) {
  check_request(request, 4);
  const SampleType stored =
      request.stored == SampleType::kUint8 ? SampleType::kUint8 : SampleType::kUint16;
  std::vector<unsigned char> pixels = request_pixels(request, stored);
  const size_t row = size_t(request.width) * size_t(request.channels) * sample_size(stored);
  std::vector<png_bytep> rows(size_t(request.height));
  for (size_t y = 0; y < rows.size(); ++y) rows[y] = pixels.data() + y * row;
  // The header's text attributes as tEXt chunks (OpenImageIO's names: ImageDescription is
  // "Description"); values stay owned by the request.
  std::vector<std::string> keys;
  std::vector<const std::string*> values;
  for (const HeaderAttribute& attribute : request.attributes)
    if (const auto* value = std::get_if<std::string>(&attribute.value)) {
      if (attribute.name.empty() || attribute.name.size() > 79) continue;  // PNG's key limit
      keys.push_back(attribute.name == "ImageDescription" ? "Description" : attribute.name);
      values.push_back(value);
    }
  std::vector<png_text> text(keys.size());
  for (size_t i = 0; i < keys.size(); ++i) {
    text[i].compression = PNG_TEXT_COMPRESSION_NONE;
    text[i].key = keys[i].data();
    text[i].text = const_cast<char*>(values[i]->c_str());
    text[i].text_length = values[i]->size();
  }
  std::vector<unsigned char> encoded;
  PngState state;
  state.output = &encoded;
  PngWriter writer;
  writer.png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &state, on_error, on_warning);
  if (writer.png) writer.info = png_create_info_struct(writer.png);
  if (!writer.png || !writer.info) throw Error(request.path, "cannot encode PNG: out of memory");
  png_set_write_fn(writer.png, &state, write_bytes, flush_nothing);
  if (!write_png(writer, request, stored == SampleType::kUint8 ? 8 : 16, text, rows))
    throw Error(request.path, std::string("cannot encode PNG: ") + state.message);
  return encoded;
}

}  // namespace obscura::codecs
