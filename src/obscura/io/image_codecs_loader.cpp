#include "obscura/io/image_codecs_loader.h"

#include <dlfcn.h>

#include <cerrno>
#include <cstdlib>
#include <filesystem>
#include <mutex>

#include "obscura/math/error.h"

#ifdef OBSCURA_STATIC_IMAGE_CODECS
// Sanitized and fuzzing builds link the codecs in (the sanitizer and coverage runtimes then see
// one program): the entry point is an ordinary function.
extern "C" const obscura::ImageCodecs* obscura_image_codecs_v1();
#endif

namespace obscura {

namespace fs = std::filesystem;

namespace {

// The file this code was loaded from: the Python extension module, or the executable. (dladdr
// names the main program by argv[0], which may be relative to another working directory, so the
// executable is taken from /proc/self/exe instead.)
fs::path binary_holding_this_library() {
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&image_codecs_search_dirs), &info) && info.dli_fname &&
      info.dli_fname[0] != '\0' && std::string(info.dli_fname) != program_invocation_name) {
    std::error_code ec;
    fs::path resolved = fs::canonical(info.dli_fname, ec);
    if (!ec) return resolved;
  }
  std::error_code ec;
  fs::path self = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::path() : self;
}

struct Loaded {
  const ImageCodecs* codecs = nullptr;
  std::string failure;
};

Loaded load() {
#ifdef OBSCURA_STATIC_IMAGE_CODECS
  return {obscura_image_codecs_v1(), ""};
#else
  std::string looked;
  for (const std::string& dir : image_codecs_search_dirs()) {
    fs::path file = fs::path(dir) / kImageCodecsPluginFile;
    std::error_code ec;
    if (!fs::is_regular_file(file, ec)) {
      looked += "\n  " + file.string() + ": not there";
      continue;
    }
    // RTLD_LOCAL: OpenImageIO's symbols stay out of the global namespace (nothing else in the
    // process resolves against them). The handle is kept for the life of the process.
    void* handle = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
      looked += "\n  " + file.string() + ": cannot load: " + dlerror();
      continue;
    }
    using Entry = const ImageCodecs* (*)();
    auto entry = reinterpret_cast<Entry>(dlsym(handle, kImageCodecsEntryPoint));
    if (!entry) {
      looked += "\n  " + file.string() + ": has no " + kImageCodecsEntryPoint +
                " (a plugin of another Obscura version)";
      continue;
    }
    return {entry(), ""};
  }
  return {nullptr, std::string("cannot read or write images: the image codecs plugin ") +
                       kImageCodecsPluginFile + " was not found or did not load; looked in:" +
                       looked + "\nset OBSCURA_PLUGIN_DIR to the folder that holds it"};
#endif
}

}  // namespace

std::vector<std::string> image_codecs_search_dirs() {
  std::vector<std::string> dirs;
  if (const char* override_dir = std::getenv("OBSCURA_PLUGIN_DIR"); override_dir && *override_dir)
    dirs.emplace_back(override_dir);
  fs::path binary = binary_holding_this_library();
  if (!binary.empty()) {
    fs::path dir = binary.parent_path();
    dirs.push_back(dir.string());
    dirs.push_back((dir.parent_path() / OBSCURA_INSTALL_LIBDIR).string());
  }
#ifdef OBSCURA_BUILD_PLUGIN_DIR
  dirs.emplace_back(OBSCURA_BUILD_PLUGIN_DIR);
#endif
  return dirs;
}

const ImageCodecs& image_codecs() {
  static std::once_flag once;
  static Loaded loaded;
  std::call_once(once, [] { loaded = load(); });
  if (!loaded.codecs) throw Error(loaded.failure);
  return *loaded.codecs;
}

}  // namespace obscura
