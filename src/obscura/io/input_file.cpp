#include "obscura/io/input_file.h"

#include <filesystem>

#include "obscura/math/error.h"

namespace obscura {

uint64_t check_input_file(const std::string& path, uint64_t max_bytes, std::string_view kind) {
  std::error_code ec;
  auto status = std::filesystem::status(path, ec);
  if (ec || !std::filesystem::exists(status)) throw Error(path, "file does not exist");
  if (std::filesystem::is_directory(status)) throw Error(path, "is a directory, not a file");
  if (!std::filesystem::is_regular_file(status))
    throw Error(path, "is not a regular file (a device, FIFO or socket)");
  uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec) throw Error(path, "cannot read: " + ec.message());
  if (size > max_bytes)
    throw Error(path, "is " + std::to_string(size >> 20) + " MiB; " + std::string(kind) + " over " +
                          std::to_string(max_bytes >> 20) + " MiB are not read");
  return size;
}

}  // namespace obscura
