#include "obscura/io/image_codecs_loader.h"

#include <mutex>
#include <string>

#include "obscura/io/plugin_loader.h"
#include "obscura/math/error.h"

#ifdef OBSCURA_STATIC_IMAGE_CODECS
// Sanitized and fuzzing builds link the codecs in (the sanitizer and coverage runtimes then see
// one program): the entry points are ordinary functions.
extern "C" const obscura::ImageCodecs* obscura_image_codecs_v2();
extern "C" const obscura::ImageCodecs* obscura_oiio_codecs_v2();
#endif

namespace obscura {

namespace {

struct Loaded {
  const ImageCodecs* codecs = nullptr;
  std::string failure;
};

Loaded load(const char* file, const char* entry_point, const char* needed_for) {
#ifdef OBSCURA_STATIC_IMAGE_CODECS
  (void)file;
  (void)needed_for;
  return {std::string(entry_point) == kImageCodecsEntryPoint ? obscura_image_codecs_v2()
                                                             : obscura_oiio_codecs_v2(),
          ""};
#else
  try {
    using Entry = const ImageCodecs* (*)();
    return {reinterpret_cast<Entry>(load_plugin_entry(file, entry_point, needed_for))(), ""};
  } catch (const Error& e) {
    return {nullptr, e.what()};
  }
#endif
}

const ImageCodecs& native_codecs() {
  static std::once_flag once;
  static Loaded loaded;
  std::call_once(once, [] {
    loaded = load(kImageCodecsPluginFile, kImageCodecsEntryPoint, "read or write images");
  });
  if (!loaded.codecs) throw Error(loaded.failure);
  return *loaded.codecs;
}

// OpenImageIO, loaded only by the first read the native codecs leave to it.
const ImageCodecs& oiio_codecs() {
  static std::once_flag once;
  static Loaded loaded;
  std::call_once(once, [] {
    loaded = load(kOiioCodecsPluginFile, kOiioCodecsEntryPoint,
                  "read BMP, Targa, PNM and the rarer TIFF and JPEG files");
  });
  if (!loaded.codecs) throw Error(loaded.failure);
  return *loaded.codecs;
}

// The native codecs first, OpenImageIO for what they leave.
class RoutedCodecs final : public ImageCodecs {
 public:
  std::unique_ptr<ImageDecoder> open(const std::string& reader, const std::string& name,
                                     bool from_memory, std::span<const uint8_t> memory,
                                     const std::string& source) const override {
    if (auto decoder = native_codecs().open(reader, name, from_memory, memory, source))
      return decoder;
    auto decoder = oiio_codecs().open(reader, name, from_memory, memory, source);
    if (!decoder) throw Error(source, "no image reader decodes it as " + reader);
    return decoder;
  }
  std::vector<unsigned char> encode(const EncodeRequest& request) const override {
    return native_codecs().encode(request);
  }
};

}  // namespace

const ImageCodecs& image_codecs() {
  native_codecs();  // a missing plugin is reported by the first call, before any work
  static const RoutedCodecs routed;
  return routed;
}

}  // namespace obscura
