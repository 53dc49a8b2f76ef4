#include "obscura/io/binary_location.h"

#include <dlfcn.h>

#include <cerrno>
#include <string>

namespace obscura {

namespace fs = std::filesystem;

fs::path binary_holding_this_library() {
  // dladdr names the shared object holding a function of the library. It names the main program
  // by argv[0] instead, which may be relative to another working directory, so the executable is
  // taken from /proc/self/exe then.
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&binary_holding_this_library), &info) && info.dli_fname &&
      info.dli_fname[0] != '\0' && std::string(info.dli_fname) != program_invocation_name) {
    std::error_code ec;
    fs::path resolved = fs::canonical(info.dli_fname, ec);
    if (!ec) return resolved;
  }
  std::error_code ec;
  fs::path self = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::path() : self;
}

}  // namespace obscura
