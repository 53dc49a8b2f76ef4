#include "obscura/io/plugin_loader.h"

#include <dlfcn.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>

#include "obscura/io/binary_location.h"
#include "obscura/math/error.h"

namespace obscura {

namespace fs = std::filesystem;

std::vector<std::string> plugin_search_dirs() {
  // The override is the only place looked in: one that a plugin found elsewhere could silently
  // bypass would not say which plugin a process runs with.
  if (const char* override_dir = std::getenv("OBSCURA_PLUGIN_DIR"); override_dir && *override_dir)
    return {override_dir};
  std::vector<std::string> dirs;
  fs::path binary = binary_holding_this_library();
  if (!binary.empty()) {
    fs::path dir = binary.parent_path();
    dirs.push_back(dir.string());
    dirs.push_back((dir.parent_path() / OBSCURA_INSTALL_LIBDIR).string());
  }
#ifdef OBSCURA_BUILD_PLUGIN_DIR
  dirs.emplace_back(OBSCURA_BUILD_PLUGIN_DIR);
#endif
  // Each folder once (the build tree is often the executable's folder), first place kept.
  std::vector<std::string> unique;
  for (const std::string& dir : dirs) {
    std::string normal = fs::path(dir).lexically_normal().string();
    if (std::find(unique.begin(), unique.end(), normal) == unique.end()) unique.push_back(normal);
  }
  return unique;
}

void* load_plugin_entry(const std::string& file, const std::string& entry_point,
                        const std::string& needed_for) {
  std::string looked;
  for (const std::string& dir : plugin_search_dirs()) {
    fs::path path = fs::path(dir) / file;
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) {
      looked += "\n  " + path.string() + ": not there";
      continue;
    }
    // RTLD_LOCAL: the plugin's libraries stay out of the global namespace (nothing else in the
    // process resolves against them).
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
      looked += "\n  " + path.string() + ": cannot load: " + dlerror();
      continue;
    }
    if (void* entry = dlsym(handle, entry_point.c_str())) return entry;
    looked += "\n  " + path.string() + ": has no " + entry_point +
              " (a plugin of another Obscura version)";
    dlclose(handle);
  }
  throw Error("cannot " + needed_for + ": the plugin " + file +
              " was not found or did not load; looked in:" + looked +
              "\nset OBSCURA_PLUGIN_DIR to the folder that holds it");
}

}  // namespace obscura
