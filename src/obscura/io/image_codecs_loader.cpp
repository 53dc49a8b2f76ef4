#include "obscura/io/image_codecs_loader.h"

#include <mutex>
#include <string>

#include "obscura/io/plugin_loader.h"
#include "obscura/math/error.h"

#ifdef OBSCURA_STATIC_IMAGE_CODECS
// Sanitized and fuzzing builds link the codecs in (the sanitizer and coverage runtimes then see
// one program): the entry point is an ordinary function.
extern "C" const obscura::ImageCodecs* obscura_image_codecs_v1();
#endif

namespace obscura {

namespace {

struct Loaded {
  const ImageCodecs* codecs = nullptr;
  std::string failure;
};

Loaded load() {
#ifdef OBSCURA_STATIC_IMAGE_CODECS
  return {obscura_image_codecs_v1(), ""};
#else
  try {
    using Entry = const ImageCodecs* (*)();
    auto entry = reinterpret_cast<Entry>(
        load_plugin_entry(kImageCodecsPluginFile, kImageCodecsEntryPoint, "read or write images"));
    return {entry(), ""};
  } catch (const Error& e) {
    return {nullptr, e.what()};
  }
#endif
}

}  // namespace

const ImageCodecs& image_codecs() {
  static std::once_flag once;
  static Loaded loaded;
  std::call_once(once, [] { loaded = load(); });
  if (!loaded.codecs) throw Error(loaded.failure);
  return *loaded.codecs;
}

}  // namespace obscura
