#include "tiff_codec.h"

#include <algorithm>
#include <cstring>
#include <ctime>
#include <string>
#include <utility>

#include "encode_attributes.h"
#include "obscura/math/error.h"
#include "sample_conversion.h"
#include "tiff_memory_stream.h"

namespace obscura::codecs {

namespace {

// The TIFF text tags read back as attributes, under OpenImageIO's names.
constexpr std::pair<ttag_t, const char*> kTextTags[] = {
    {TIFFTAG_IMAGEDESCRIPTION, "ImageDescription"},
    {TIFFTAG_SOFTWARE, "Software"},
    {TIFFTAG_DATETIME, "DateTime"},
    {TIFFTAG_ARTIST, "Artist"},
    {TIFFTAG_COPYRIGHT, "Copyright"},
    {TIFFTAG_DOCUMENTNAME, "DocumentName"},
    {TIFFTAG_HOSTCOMPUTER, "HostComputer"},
    {TIFFTAG_MAKE, "Make"},
    {TIFFTAG_MODEL, "Model"},
};

struct TiffCloser {
  void operator()(TIFF* tif) const { TIFFClose(tif); }
};
using TiffHandle = std::unique_ptr<TIFF, TiffCloser>;

// The stored type of `bits`-bit samples of `format`, or kOther when this reader leaves them.
SampleType stored_type(uint16_t bits, uint16_t format) {
  if (format == SAMPLEFORMAT_UINT && bits == 8) return SampleType::kUint8;
  if (format == SAMPLEFORMAT_UINT && bits == 16) return SampleType::kUint16;
  if (format == SAMPLEFORMAT_IEEEFP && bits == 16) return SampleType::kHalf;
  if (format == SAMPLEFORMAT_IEEEFP && bits == 32) return SampleType::kFloat;
  return SampleType::kOther;
}

class TiffDecoder final : public StoredImageDecoder {
 public:
  explicit TiffDecoder(EncodedBytes encoded) : encoded_(std::move(encoded)) {
    stream_.input = encoded_.bytes;
    tif_.reset(open_tiff_stream(stream_, "rm", encoded_.source));
    if (!tif_) fail("");
    header_.format_name = "tiff";
    uint32_t width = 0, height = 0, depth = 1;
    uint16_t channels = 1, bits = 1, format = SAMPLEFORMAT_UINT, photometric = 0, planar = 1;
    TIFFGetField(tif_.get(), TIFFTAG_IMAGEWIDTH, &width);
    TIFFGetField(tif_.get(), TIFFTAG_IMAGELENGTH, &height);
    TIFFGetFieldDefaulted(tif_.get(), TIFFTAG_IMAGEDEPTH, &depth);
    TIFFGetFieldDefaulted(tif_.get(), TIFFTAG_SAMPLESPERPIXEL, &channels);
    TIFFGetFieldDefaulted(tif_.get(), TIFFTAG_BITSPERSAMPLE, &bits);
    TIFFGetFieldDefaulted(tif_.get(), TIFFTAG_SAMPLEFORMAT, &format);
    TIFFGetFieldDefaulted(tif_.get(), TIFFTAG_PLANARCONFIG, &planar);
    if (!TIFFGetField(tif_.get(), TIFFTAG_PHOTOMETRIC, &photometric))
      fail("the directory has no PhotometricInterpretation");
    header_.width = int(std::min<uint32_t>(width, INT32_MAX));
    header_.height = int(std::min<uint32_t>(height, INT32_MAX));
    header_.depth = int(std::min<uint32_t>(depth, INT32_MAX));
    header_.channels = channels;
    header_.format = stored_type(bits, format);
    header_.channel_names = default_channel_names(header_.channels);
    supported_ = header_.format != SampleType::kOther && channels >= 1 && channels <= 4 &&
                 planar == PLANARCONFIG_CONTIG &&
                 (photometric == PHOTOMETRIC_MINISBLACK ||
                  (photometric == PHOTOMETRIC_RGB && channels >= 3));
    for (const auto& [tag, name] : kTextTags) {
      const char* text = nullptr;
      if (TIFFGetField(tif_.get(), tag, &text) && text)
        header_.text_attributes.emplace_back(name, text);
    }
  }
  bool supported() const { return supported_; }

 private:
  [[noreturn]] void fail(const std::string& why) const {
    std::string message = why.empty() ? stream_.errors : why;
    throw Error(encoded_.source,
                "cannot read image as tiff" + (message.empty() ? "" : ": " + message));
  }

  void decode_stored(void* pixels) override {
    auto* out = static_cast<unsigned char*>(pixels);
    const size_t pixel_bytes = size_t(header_.channels) * sample_size(header_.format);
    const size_t row_bytes = size_t(header_.width) * pixel_bytes;
    if (uint64_t(TIFFScanlineSize64(tif_.get())) != row_bytes) fail("unexpected scanline size");
    if (TIFFIsTiled(tif_.get())) return decode_tiles(out, pixel_bytes, row_bytes);
    uint32_t rows_per_strip = 0;
    TIFFGetFieldDefaulted(tif_.get(), TIFFTAG_ROWSPERSTRIP, &rows_per_strip);
    rows_per_strip = std::clamp<uint32_t>(rows_per_strip, 1, uint32_t(header_.height));
    for (uint32_t y = 0; y < uint32_t(header_.height); y += rows_per_strip) {
      const uint32_t rows = std::min<uint32_t>(rows_per_strip, uint32_t(header_.height) - y);
      const tmsize_t want = tmsize_t(rows * row_bytes);
      tmsize_t got = TIFFReadEncodedStrip(tif_.get(), TIFFComputeStrip(tif_.get(), y, 0),
                                          out + size_t(y) * row_bytes, want);
      if (got != want) fail("");
    }
  }

  void decode_tiles(unsigned char* out, size_t pixel_bytes, size_t row_bytes) {
    uint32_t tile_width = 0, tile_height = 0;
    TIFFGetField(tif_.get(), TIFFTAG_TILEWIDTH, &tile_width);
    TIFFGetField(tif_.get(), TIFFTAG_TILELENGTH, &tile_height);
    const tmsize_t tile_bytes = TIFFTileSize(tif_.get());
    if (tile_width == 0 || tile_height == 0 || tile_bytes <= 0 ||
        uint64_t(tile_bytes) != uint64_t(tile_width) * tile_height * pixel_bytes)
      fail("unexpected tile size");
    std::vector<unsigned char> tile(static_cast<size_t>(tile_bytes));
    for (uint32_t ty = 0; ty < uint32_t(header_.height); ty += tile_height)
      for (uint32_t tx = 0; tx < uint32_t(header_.width); tx += tile_width) {
        if (TIFFReadTile(tif_.get(), tile.data(), tx, ty, 0, 0) < 0) fail("");
        const uint32_t rows = std::min(tile_height, uint32_t(header_.height) - ty);
        const uint32_t columns = std::min(tile_width, uint32_t(header_.width) - tx);
        for (uint32_t r = 0; r < rows; ++r)
          std::memcpy(out + size_t(ty + r) * row_bytes + size_t(tx) * pixel_bytes,
                      tile.data() + size_t(r) * tile_width * pixel_bytes, columns * pixel_bytes);
      }
  }

  EncodedBytes encoded_;
  TiffMemoryStream stream_;
  TiffHandle tif_;
  bool supported_ = false;
};

}  // namespace

std::unique_ptr<ImageDecoder> open_tiff(EncodedBytes encoded) {
  auto decoder = std::make_unique<TiffDecoder>(std::move(encoded));
  if (!decoder->supported()) return nullptr;
  return decoder;
}

std::vector<unsigned char> encode_tiff(const EncodeRequest& request) {
  check_request(request, 4);
  const SampleType stored =
      request.stored == SampleType::kOther ? SampleType::kFloat : request.stored;
  std::vector<unsigned char> pixels = request_pixels(request, stored);
  std::vector<unsigned char> encoded;
  TiffMemoryStream stream;
  stream.output = &encoded;
  TiffHandle tif(open_tiff_stream(stream, "w", request.path));
  if (!tif) throw Error(request.path, "cannot encode TIFF: " + stream.errors);
  TIFF* t = tif.get();
  const bool floating = stored == SampleType::kHalf || stored == SampleType::kFloat;
  TIFFSetField(t, TIFFTAG_IMAGEWIDTH, uint32_t(request.width));
  TIFFSetField(t, TIFFTAG_IMAGELENGTH, uint32_t(request.height));
  TIFFSetField(t, TIFFTAG_SAMPLESPERPIXEL, uint16_t(request.channels));
  TIFFSetField(t, TIFFTAG_BITSPERSAMPLE, uint16_t(8 * sample_size(stored)));
  TIFFSetField(t, TIFFTAG_SAMPLEFORMAT, floating ? SAMPLEFORMAT_IEEEFP : SAMPLEFORMAT_UINT);
  TIFFSetField(t, TIFFTAG_PHOTOMETRIC,
               request.channels >= 3 ? PHOTOMETRIC_RGB : PHOTOMETRIC_MINISBLACK);
  if (request.channels == 2 || request.channels == 4) {
    // Alpha marked associated, as OpenImageIO wrote it (Obscura writes no partly transparent
    // display images that would differ).
    uint16_t extra = EXTRASAMPLE_ASSOCALPHA;
    TIFFSetField(t, TIFFTAG_EXTRASAMPLES, uint16_t(1), &extra);
  }
  TIFFSetField(t, TIFFTAG_PLANARCONFIG, PLANARCONFIG_CONTIG);
  TIFFSetField(t, TIFFTAG_ORIENTATION, ORIENTATION_TOPLEFT);
  TIFFSetField(t, TIFFTAG_COMPRESSION, COMPRESSION_ADOBE_DEFLATE);
  TIFFSetField(t, TIFFTAG_PREDICTOR,
               stored == SampleType::kFloat ? PREDICTOR_FLOATINGPOINT : PREDICTOR_HORIZONTAL);
  TIFFSetField(t, TIFFTAG_ROWSPERSTRIP, uint32_t(32));
  for (const auto& [tag, name] : kTextTags)
    if (const std::string* text = text_attribute(request, name))
      TIFFSetField(t, tag, text->c_str());
  if (!text_attribute(request, "DateTime"))
    TIFFSetField(t, TIFFTAG_DATETIME, now_as_tiff_date().c_str());
  const size_t row_bytes = size_t(request.width) * size_t(request.channels) * sample_size(stored);
  for (uint32_t y = 0; y < uint32_t(request.height); ++y)
    if (TIFFWriteScanline(t, pixels.data() + y * row_bytes, y, 0) < 0)
      throw Error(request.path, "cannot encode TIFF: " + stream.errors);
  if (!TIFFWriteDirectory(t)) throw Error(request.path, "cannot encode TIFF: " + stream.errors);
  tif.reset();  // TIFFClose flushes nothing more: the directory is written
  return encoded;
}

}  // namespace obscura::codecs
