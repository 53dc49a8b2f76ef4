#include "oiio_decoder.h"

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <utility>
#include <vector>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include "obscura/math/error.h"
#include "oiio_types.h"

namespace obscura::oiio {

namespace {

// Reads from bytes in memory for OpenImageIO. (OpenImageIO 2.4's IOMemReader copies past its
// buffer when a reader asks for an offset beyond the end, which a corrupt file makes OpenEXR
// do: found by fuzz/image_fuzz.cpp.) Reads past the end return fewer bytes, never more.
//
// It is an IOMemReader (proxy type "memreader") because some OpenImageIO 2.4 readers — JPEG —
// accept no other proxy: they take the whole buffer from it (libjpeg's bounded memory source)
// instead of calling read().
class BoundedMemoryReader final : public OIIO::Filesystem::IOMemReader {
 public:
  explicit BoundedMemoryReader(std::span<const uint8_t> bytes)
      : IOMemReader(bytes.data(), bytes.size()), bytes_(bytes) {}
  size_t read(void* buffer, size_t size) override {
    size_t n = pread(buffer, size, m_pos);
    m_pos += int64_t(n);
    return n;
  }
  size_t pread(void* buffer, size_t size, int64_t offset) override {
    if (offset < 0 || uint64_t(offset) >= bytes_.size()) return 0;
    size_t n = std::min(size, bytes_.size() - size_t(offset));
    std::memcpy(buffer, bytes_.data() + offset, n);
    return n;
  }
  size_t size() const override { return bytes_.size(); }

 private:
  std::span<const uint8_t> bytes_;
};

ImageHeader header_of(const OIIO::ImageSpec& spec, const char* format_name) {
  ImageHeader h;
  h.width = spec.width;
  h.height = spec.height;
  h.depth = spec.depth;
  h.channels = spec.nchannels;
  h.deep = spec.deep;
  h.format = sample_type(spec.format);
  h.channel_names = spec.channelnames;
  for (const OIIO::ParamValue& p : spec.extra_attribs)
    if (p.type() == OIIO::TypeDesc::STRING)
      h.text_attributes.emplace_back(p.name().string(), p.get_string());
  h.format_name = format_name;
  return h;
}

class OiioDecoder final : public ImageDecoder {
 public:
  OiioDecoder(std::string source, std::unique_ptr<BoundedMemoryReader> memory,
              std::unique_ptr<OIIO::ImageInput> input)
      : source_(std::move(source)),
        memory_(std::move(memory)),
        input_(std::move(input)),
        header_(header_of(input_->spec(), input_->format_name())) {}

  const ImageHeader& header() const override { return header_; }
  void read(int channels, SampleType type, void* pixels) override;

 private:
  std::string source_;
  std::unique_ptr<BoundedMemoryReader> memory_;  // the proxy input_ reads through
  std::unique_ptr<OIIO::ImageInput> input_;
  ImageHeader header_;
};

void OiioDecoder::read(int channels, SampleType sample, void* pixels) {
  const OIIO::TypeDesc type = type_desc(sample);
  const OIIO::ImageSpec& spec = input_->spec();
  // OpenImageIO 2.4 reads a scanline image through a buffer of 64 MiB, whatever the image's size
  // (every 4 × 4 texture allocated it), unless the read asks for TypeDesc::UNKNOWN — the file's
  // own types — even when the type asked is the file's. So: read that way, into a buffer of the
  // image's size, and convert here.
  auto read_native = [&](void* out) {
    if (!input_->read_image(0, 0, 0, channels, OIIO::TypeDesc::UNKNOWN, out))
      throw Error(source_, "cannot decode image: " + input_->geterror());
  };
  auto unconvertible = [&](OIIO::TypeDesc from) {
    return Error(source_, "cannot convert the image's " + std::string(from.c_str()) +
                              " values to " + type.c_str());
  };
  if (spec.channelformats.empty() && spec.format == type) return read_native(pixels);
  size_t pixel_count = size_t(spec.width) * size_t(spec.height);
  size_t native_pixel_bytes = spec.pixel_bytes(0, channels, true);
  std::vector<std::byte> native(pixel_count * native_pixel_bytes);
  read_native(native.data());
  auto* out = static_cast<std::byte*>(pixels);
  if (spec.channelformats.empty()) {
    // In pieces: the count is an int, and a raised pixel limit may pass more values than it holds.
    size_t values = pixel_count * size_t(channels);
    constexpr size_t kPiece = size_t(1) << 24;
    for (size_t first = 0; first < values; first += kPiece) {
      int n = int(std::min(kPiece, values - first));
      if (!OIIO::convert_pixel_values(spec.format, native.data() + first * spec.format.size(), type,
                                      out + first * type.size(), n))
        throw unconvertible(spec.format);
    }
    return;
  }
  // Channels stored in different types (an OpenEXR with half colour and float depth): one
  // channel at a time, each from its own type.
  size_t offset = 0;
  OIIO::stride_t out_pixel_bytes = OIIO::stride_t(channels) * OIIO::stride_t(type.size());
  for (int c = 0; c < channels; ++c) {
    OIIO::TypeDesc from = spec.channelformats[size_t(c)];
    if (!OIIO::convert_image(1, spec.width, spec.height, 1, native.data() + offset, from,
                             OIIO::stride_t(native_pixel_bytes),
                             OIIO::stride_t(native_pixel_bytes) * spec.width, OIIO::AutoStride,
                             out + size_t(c) * type.size(), type, out_pixel_bytes,
                             out_pixel_bytes * spec.width, OIIO::AutoStride))
      throw unconvertible(from);
    offset += from.size();
  }
}

}  // namespace

std::unique_ptr<ImageDecoder> open_image(const std::string& reader, const std::string& name,
                                         bool from_memory, std::span<const uint8_t> memory,
                                         const std::string& source) {
  // OpenImageIO 2.4's TIFF reader decompresses zip strips on its thread pool and, when a strip
  // read fails, returns before those tasks finish: they go on reading its freed scratch buffer
  // and writing into the caller's pixels after the read has failed (a published advisory, fixed
  // upstream in 3.1.16; the image fuzz target met it as heap corruption in a freed block).
  // Decompressing on the calling thread closes it, at the cost of parallel decompression of zip
  // TIFFs.
  static const bool tiff_serial = OIIO::attribute("tiff:multithread", 0);
  (void)tiff_serial;
  std::unique_ptr<BoundedMemoryReader> proxy;
  if (from_memory) proxy = std::make_unique<BoundedMemoryReader>(memory);
  OIIO::ImageSpec config;
  if (proxy) {
    void* p = proxy.get();
    config.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &p);
  }
  // Colour as stored, never multiplied by alpha: OpenImageIO premultiplies the straight alpha of
  // PNG, Targa and the like by default, which darkened every partly transparent texel of a glTF
  // texture (whose alpha is straight by the specification) — by 2× on AlphaBlendModeTest's
  // cutoff panels, against Cycles. Files that store premultiplied colour (OpenEXR) keep it.
  config.attribute("oiio:UnassociatedAlpha", 1);
  // create() with do_open = false picks the reader by name and never falls back to others.
  std::unique_ptr<OIIO::ImageInput> input = OIIO::ImageInput::create(reader, false, &config);
  if (!input) throw Error(source, "cannot read image: " + OIIO::geterror());
  OIIO::ImageSpec spec;
  bool opened = input->open(name, spec, config);
  if (!opened) {
    std::string why = input->geterror();
    if (why.empty()) why = OIIO::geterror();
    throw Error(source, "cannot read image as " + reader + (why.empty() ? "" : ": " + why));
  }
  return std::make_unique<OiioDecoder>(source, std::move(proxy), std::move(input));
}

}  // namespace obscura::oiio
