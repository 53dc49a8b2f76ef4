// The boundary between Obscura and the image codecs. They live in two plugins, loaded on first
// use (image_codecs_loader.h), so that a process that never touches an image file (`obscura
// --version`, `import obscura`) loads none of their libraries:
//  - libobscura_image_codecs.so: PNG, JPEG, TIFF, OpenEXR and Radiance HDR through libpng,
//    libjpeg, libtiff and OpenEXR directly, and PFM (plugins/image_codecs), loaded on the first
//    image read or write: a few milliseconds;
//  - libobscura_oiio_codecs.so: OpenImageIO (plugins/oiio_codecs), for the readers the first does
//    not have (BMP, Targa, PNM other than PFM, rare TIFF and JPEG layouts): some 250 shared
//    libraries, ~0.25 s and ~100 MB, loaded only when such a file is read.
//
// Only plain types cross the boundary, so no header outside the plugins names a codec's type.
// Both sides are built together by the one CMake project (same compiler, same standard library);
// the entry point's name carries kImageCodecsAbi, so a stale plugin is refused rather than misread.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace obscura {

// Types of stored or requested pixel values (kOther: stored in a type no caller asks for).
enum class SampleType { kUint8, kUint16, kHalf, kFloat, kOther };

// What an opened image file's header says, as far as Obscura uses it.
struct ImageHeader {
  int width = 0;
  int height = 0;
  int depth = 1;     // > 1 for volume images, which are refused
  int channels = 0;  // all the file's channels
  bool deep = false;
  SampleType format = SampleType::kOther;  // the file's (first channel's) stored type
  std::vector<std::string> channel_names;
  // The header's string-valued attributes in file order ("ImageDescription" among them).
  std::vector<std::pair<std::string, std::string>> text_attributes;
  std::string format_name;  // the reader: "openexr", "png", …

  bool has_attribute(const std::string& name) const {
    for (const auto& attribute : text_attributes)
      if (attribute.first == name) return true;
    return false;
  }
};

// An opened image whose header has been read; nothing is decoded until read().
class ImageDecoder {
 public:
  virtual ~ImageDecoder() = default;
  virtual const ImageHeader& header() const = 0;
  // Decodes subimage 0's channels [0, channels) as `type` (not kOther) into `pixels`, which
  // holds width × height × channels values. Throws obscura::Error naming the source on failure.
  virtual void read(int channels, SampleType type, void* pixels) = 0;
};

// A header attribute to write: text, an integer, or floats (EXR chromaticities).
struct HeaderAttribute {
  std::string name;
  std::variant<std::string, int, std::vector<float>> value;
};

// One image to encode: the format follows `path`'s extension (PNG, JPEG, TIFF, EXR, HDR).
struct EncodeRequest {
  std::string path;  // the final file's name: for the format and for messages
  int width = 0;
  int height = 0;
  int channels = 0;
  SampleType stored = SampleType::kFloat;   // the file's sample type
  std::vector<std::string> channel_names;   // empty: the format's defaults
  std::vector<HeaderAttribute> attributes;  // in order
  SampleType data_type = SampleType::kFloat;
  const void* data = nullptr;  // width × height × channels values of data_type
};

// The codecs one plugin provides. Errors are thrown as obscura::Error (header-only, so both sides
// throw and catch the same type).
class ImageCodecs {
 public:
  virtual ~ImageCodecs() = default;
  // Opens an image with the named reader ("png", "openexr", … — never a fallback to other
  // readers): from the file `name`, or, when `from_memory`, from `memory` (which must outlive the
  // decoder; `name` is then only a name). `source` names the image in messages. Returns nullptr
  // when these codecs do not decode the reader's format, or this file's layout of it (the next
  // plugin is then asked); throws obscura::Error when the file is not a valid one.
  virtual std::unique_ptr<ImageDecoder> open(const std::string& reader, const std::string& name,
                                             bool from_memory, std::span<const uint8_t> memory,
                                             const std::string& source) const = 0;
  // Encodes the image in memory and returns the file's bytes; writes nothing to `path`.
  virtual std::vector<unsigned char> encode(const EncodeRequest& request) const = 0;
};

// Bumped whenever a type above, or what a function returns, changes (2: open() may return nullptr).
inline constexpr int kImageCodecsAbi = 2;
// The plugins' file names and their one exported function each, `const ImageCodecs* NAME()`.
inline constexpr const char* kImageCodecsPluginFile = "libobscura_image_codecs.so";
inline constexpr const char* kImageCodecsEntryPoint = "obscura_image_codecs_v2";
inline constexpr const char* kOiioCodecsPluginFile = "libobscura_oiio_codecs.so";
inline constexpr const char* kOiioCodecsEntryPoint = "obscura_oiio_codecs_v2";

}  // namespace obscura
