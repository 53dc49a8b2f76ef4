#include "dng_codec.h"

#include <cstring>
#include <ctime>
#include <memory>
#include <string>

#include "encode_attributes.h"
#include "obscura/math/error.h"
#include "sample_conversion.h"
#include "tiff_memory_stream.h"

namespace obscura::codecs {

namespace {

// DNG's PhotometricInterpretation for demosaiced (or monochrome) raw data; libtiff 4.5's tiff.h
// names CFA (32803) but not this one.
constexpr uint16_t kPhotometricLinearRaw = 34892;

struct TiffCloser {
  void operator()(TIFF* tif) const { TIFFClose(tif); }
};

const std::vector<float>* float_attribute(const EncodeRequest& request, const std::string& name) {
  for (const HeaderAttribute& attribute : request.attributes)
    if (attribute.name == name)
      if (const auto* floats = std::get_if<std::vector<float>>(&attribute.value)) return floats;
  return nullptr;
}

const int* int_attribute(const EncodeRequest& request, const std::string& name) {
  for (const HeaderAttribute& attribute : request.attributes)
    if (attribute.name == name)
      if (const auto* value = std::get_if<int>(&attribute.value)) return value;
  return nullptr;
}

// Sets an array-valued tag, passing the count when libtiff's field takes one (its field tables
// changed between versions: CFAPattern is a fixed 4 bytes in some, a counted array in others).
template <typename T>
bool set_array(TIFF* t, uint32_t tag, const T* values, uint16_t count) {
  const TIFFField* field = TIFFFieldWithTag(t, tag);
  if (!field) return false;
  if (TIFFFieldPassCount(field)) return TIFFSetField(t, tag, count, values) == 1;
  return TIFFSetField(t, tag, values) == 1;
}

// The CFA colours (0 red, 1 green, 2 blue) of a 2 × 2 pattern named in reading order.
bool cfa_colours(const std::string& name, uint8_t colours[4]) {
  if (name.size() != 4) return false;
  for (int i = 0; i < 4; ++i) {
    const char c = name[size_t(i)];
    colours[i] = c == 'R' ? 0 : c == 'G' ? 1 : c == 'B' ? 2 : 255;
    if (colours[i] == 255) return false;
  }
  return true;
}

}  // namespace

std::vector<unsigned char> encode_dng(const EncodeRequest& request) {
  check_request(request, 3);
  // One channel with a CFAPattern is a mosaic; without one, a monochrome LinearRaw image.
  const bool cfa = request.channels == 1 && text_attribute(request, "CFAPattern");
  if (request.channels != 1 && request.channels != 3)
    throw Error(request.path,
                "a DNG holds a one-channel mosaic or monochrome image, or three "
                "channels of linear raw");
  // 16-bit samples are written from the caller's buffer as they are (uncompressed, native byte
  // order: libtiff copies them without changing them); other types are converted first.
  std::vector<unsigned char> converted;
  const unsigned char* pixels = static_cast<const unsigned char*>(request.data);
  if (request.data_type != SampleType::kUint16) {
    converted = request_pixels(request, SampleType::kUint16);
    pixels = converted.data();
  }
  const size_t pixel_bytes = size_t(request.width) * size_t(request.height) * request.channels * 2;
  std::vector<unsigned char> encoded;
  // The pixels uncompressed plus room for the tags: one allocation, no regrowth while libtiff
  // writes strip by strip.
  encoded.reserve(pixel_bytes + 65536);
  TiffMemoryStream stream;
  stream.output = &encoded;
  std::unique_ptr<TIFF, TiffCloser> tif(open_tiff_stream(stream, "w", request.path));
  if (!tif) throw Error(request.path, "cannot encode DNG: " + stream.errors);
  TIFF* t = tif.get();
  auto fail = [&](const std::string& what) {
    throw Error(request.path, "cannot encode DNG: " + what +
                                  (stream.errors.empty() ? "" : " (" + stream.errors + ")"));
  };
  TIFFSetField(t, TIFFTAG_SUBFILETYPE, uint32_t(0));  // the main (full-resolution raw) image
  TIFFSetField(t, TIFFTAG_IMAGEWIDTH, uint32_t(request.width));
  TIFFSetField(t, TIFFTAG_IMAGELENGTH, uint32_t(request.height));
  TIFFSetField(t, TIFFTAG_SAMPLESPERPIXEL, uint16_t(request.channels));
  TIFFSetField(t, TIFFTAG_BITSPERSAMPLE, uint16_t(16));
  TIFFSetField(t, TIFFTAG_SAMPLEFORMAT, SAMPLEFORMAT_UINT);
  TIFFSetField(t, TIFFTAG_PHOTOMETRIC, cfa ? PHOTOMETRIC_CFA : kPhotometricLinearRaw);
  TIFFSetField(t, TIFFTAG_PLANARCONFIG, PLANARCONFIG_CONTIG);
  TIFFSetField(t, TIFFTAG_ORIENTATION, ORIENTATION_TOPLEFT);
  TIFFSetField(t, TIFFTAG_COMPRESSION, COMPRESSION_NONE);
  TIFFSetField(t, TIFFTAG_ROWSPERSTRIP, uint32_t(32));
  static const uint8_t kDngVersion[4] = {1, 4, 0, 0}, kBackwardVersion[4] = {1, 1, 0, 0};
  if (!set_array(t, TIFFTAG_DNGVERSION, kDngVersion, 4) ||
      !set_array(t, TIFFTAG_DNGBACKWARDVERSION, kBackwardVersion, 4))
    fail("libtiff does not know the DNG version tags");
  for (const auto& [tag, name] :
       {std::pair{TIFFTAG_MAKE, "Make"}, std::pair{TIFFTAG_MODEL, "Model"},
        std::pair{TIFFTAG_UNIQUECAMERAMODEL, "UniqueCameraModel"},
        std::pair{TIFFTAG_SOFTWARE, "Software"},
        std::pair{TIFFTAG_IMAGEDESCRIPTION, "ImageDescription"}})
    if (const std::string* text = text_attribute(request, name))
      TIFFSetField(t, tag, text->c_str());
  const std::string* date = text_attribute(request, "DateTime");
  TIFFSetField(t, TIFFTAG_DATETIME, date ? date->c_str() : now_as_tiff_date().c_str());
  if (cfa) {
    const std::string* pattern = text_attribute(request, "CFAPattern");
    uint8_t colours[4];
    if (!pattern || !cfa_colours(*pattern, colours))
      fail("a CFA image needs a CFAPattern of R, G and B letters, e.g. RGGB");
    static const uint16_t kRepeat[2] = {2, 2};
    static const uint8_t kPlaneColours[3] = {0, 1, 2};
    if (!set_array(t, TIFFTAG_CFAREPEATPATTERNDIM, kRepeat, 2) ||
        !set_array(t, TIFFTAG_CFAPATTERN, colours, 4) ||
        !set_array(t, TIFFTAG_CFAPLANECOLOR, kPlaneColours, 3))
      fail("libtiff refused the CFA tags");
    TIFFSetField(t, TIFFTAG_CFALAYOUT, uint16_t(1));  // rectangular
  }
  if (const std::vector<float>* black = float_attribute(request, "BlackLevel"))
    set_array(t, TIFFTAG_BLACKLEVEL, black->data(), uint16_t(black->size()));
  if (const int* white = int_attribute(request, "WhiteLevel")) {
    const uint32_t level = uint32_t(*white);
    set_array(t, TIFFTAG_WHITELEVEL, &level, 1);
  }
  for (const auto& [tag, name] : {std::pair{TIFFTAG_COLORMATRIX1, "ColorMatrix1"},
                                  std::pair{TIFFTAG_COLORMATRIX2, "ColorMatrix2"},
                                  std::pair{TIFFTAG_ASSHOTNEUTRAL, "AsShotNeutral"}})
    if (const std::vector<float>* values = float_attribute(request, name))
      if (!set_array(t, tag, values->data(), uint16_t(values->size())))
        fail(std::string("libtiff refused ") + name);
  for (const auto& [tag, name] :
       {std::pair{TIFFTAG_CALIBRATIONILLUMINANT1, "CalibrationIlluminant1"},
        std::pair{TIFFTAG_CALIBRATIONILLUMINANT2, "CalibrationIlluminant2"}})
    if (const int* value = int_attribute(request, name)) TIFFSetField(t, tag, uint16_t(*value));
  if (const std::vector<float>* ev = float_attribute(request, "BaselineExposure"))
    if (!ev->empty()) TIFFSetField(t, TIFFTAG_BASELINEEXPOSURE, double((*ev)[0]));
  const size_t row_bytes = size_t(request.width) * size_t(request.channels) * 2;
  for (uint32_t y = 0; y < uint32_t(request.height); ++y)
    if (TIFFWriteScanline(t, const_cast<unsigned char*>(pixels) + y * row_bytes, y, 0) < 0)
      fail("a row");
  if (!TIFFWriteDirectory(t)) fail("the directory");
  tif.reset();
  return encoded;
}

}  // namespace obscura::codecs
