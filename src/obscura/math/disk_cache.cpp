#include "obscura/math/disk_cache.h"

#include <unistd.h>

#include <algorithm>
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

// Keeps the folder within kCacheFolderBytes: the oldest entries (by write time) go first. Other
// processes may be adding and removing entries meanwhile: every failure is ignored.
void trim(const fs::path& folder, const fs::path& keep) {
  std::error_code error;
  std::vector<std::pair<fs::file_time_type, fs::path>> entries;
  uintmax_t total = 0;
  for (fs::directory_iterator it(folder, error), end; !error && it != end; it.increment(error)) {
    if (!it->is_regular_file(error) || it->path().filename().string().front() == '.') continue;
    const uintmax_t size = it->file_size(error);
    if (error) continue;
    total += size;
    entries.emplace_back(it->last_write_time(error), it->path());
  }
  if (total <= kCacheFolderBytes) return;
  std::sort(entries.begin(), entries.end());
  for (const auto& [time, path] : entries) {
    if (total <= kCacheFolderBytes) break;
    if (path == keep) continue;
    const uintmax_t size = fs::file_size(path, error);
    if (!error && fs::remove(path, error)) total -= size;
  }
}

}  // namespace

uint64_t content_hash(std::span<const std::byte> bytes) {
  // Eight bytes at a time through a multiply–xorshift mixer (splitmix64's finaliser).
  auto mix = [](uint64_t z) {
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  };
  uint64_t h = mix(bytes.size() + 0x9e3779b97f4a7c15ull);
  size_t i = 0;
  for (; i + 8 <= bytes.size(); i += 8) {
    uint64_t word;
    std::memcpy(&word, bytes.data() + i, 8);
    h = mix(h ^ word) + 0x9e3779b97f4a7c15ull;
  }
  uint64_t tail = 0;
  if (i < bytes.size()) std::memcpy(&tail, bytes.data() + i, bytes.size() - i);
  return mix(h ^ tail);
}

std::string hex64(uint64_t value) {
  static const char* const kDigits = "0123456789abcdef";
  std::string text(16, '0');
  for (int i = 15; i >= 0; --i, value >>= 4) text[size_t(i)] = kDigits[value & 15];
  return text;
}

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
  if (error) {
    fs::remove(temporary, error);
    return false;
  }
  trim(*folder, *folder / name);
  return true;
}

}  // namespace obscura
