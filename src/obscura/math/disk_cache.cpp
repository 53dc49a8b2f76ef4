#include "obscura/math/disk_cache.h"

#include <unistd.h>

#include <cctype>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <system_error>

namespace obscura {

namespace {

namespace fs = std::filesystem;

constexpr size_t kChecksumBytes = sizeof(uint64_t);

// FNV-1a over the bytes: catches a truncated, padded or otherwise damaged entry.
uint64_t checksum(std::span<const std::byte> bytes) {
  uint64_t h = 14695981039346656037ull;
  for (std::byte b : bytes) h = (h ^ uint64_t(b)) * 1099511628211ull;
  return h;
}

std::optional<fs::path> cache_folder() {
  if (const char* dir = std::getenv("OBSCURA_CACHE_DIR")) {
    if (std::strcmp(dir, "off") == 0 || *dir == '\0') return std::nullopt;
    return fs::path(dir);
  }
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg == '/')
    return fs::path(xdg) / "obscura";
  if (const char* home = std::getenv("HOME"); home && *home == '/')
    return fs::path(home) / ".cache" / "obscura";
  return std::nullopt;
}

// Entry names are the caller's own identifiers: nothing that could leave the folder.
bool plain_name(const std::string& name) {
  if (name.empty() || name.size() > 200) return false;
  for (char c : name)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.'))
      return false;
  return name.front() != '.';
}

}  // namespace

std::optional<std::vector<std::byte>> read_cached_table(const std::string& name, size_t size) {
  const std::optional<fs::path> folder = cache_folder();
  if (!folder || !plain_name(name)) return std::nullopt;
  const fs::path path = *folder / name;
  std::error_code error;
  if (!fs::is_regular_file(path, error) || fs::file_size(path, error) != size + kChecksumBytes ||
      error)
    return std::nullopt;
  std::ifstream in(path, std::ios::binary);
  std::vector<std::byte> bytes(size);
  uint64_t stored = 0;
  in.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(size));
  in.read(reinterpret_cast<char*>(&stored), std::streamsize(kChecksumBytes));
  if (!in || in.peek() != std::char_traits<char>::eof() || stored != checksum(bytes))
    return std::nullopt;
  return bytes;
}

bool write_cached_table(const std::string& name, std::span<const std::byte> bytes) {
  const std::optional<fs::path> folder = cache_folder();
  if (!folder || !plain_name(name)) return false;
  std::error_code error;
  fs::create_directories(*folder, error);
  if (error) return false;
  // A name of this process's own, so that two processes filling the same entry do not mix.
  const fs::path temporary = *folder / ("." + name + "." + std::to_string(::getpid()) + ".partial");
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    const uint64_t sum = checksum(bytes);
    out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    out.write(reinterpret_cast<const char*>(&sum), std::streamsize(kChecksumBytes));
    out.close();
    if (!out) {
      fs::remove(temporary, error);
      return false;
    }
  }
  fs::rename(temporary, *folder / name, error);
  if (error) fs::remove(temporary, error);
  return !error;
}

}  // namespace obscura
