// A folder of tables that are expensive to compute and identical from run to run (the spectral
// lift's fitted coefficients: about a second in a release build, half a minute under the
// sanitizers), kept between processes so that each computes them once, not every run.
//
// The folder: $OBSCURA_CACHE_DIR, else $XDG_CACHE_HOME/obscura, else $HOME/.cache/obscura;
// OBSCURA_CACHE_DIR=off (or no home at all) turns the cache off. An entry is a regular file with
// the bytes and a checksum after them; one that is missing, of another size, not a regular file
// (a FIFO would block a read) or whose checksum disagrees is a miss, and the caller computes
// the table again. Writes go to a temporary file renamed into place, so a reader never sees half
// an entry; a folder that cannot be written only means the next run computes again.
//
// The name must change whenever the bytes would: callers put a key of the code and the compiler
// that made them into it (CMake's OBSCURA_TABLE_KEY) and, for a table made from data (an
// environment map), a content_hash of that data. The folder holds at most kCacheFolderBytes of
// entries: storing one beyond that removes the least recently written first.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <optional>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

namespace obscura {

inline constexpr size_t kCacheFolderBytes = size_t(256) << 20;

// A 64-bit hash of `bytes` for naming entries by content (not cryptographic: a cache key).
uint64_t content_hash(std::span<const std::byte> bytes);
// `value` as 16 hexadecimal digits, for entry names.
std::string hex64(uint64_t value);

// The entry `name` if it holds exactly `size` bytes with a good checksum.
std::optional<std::vector<std::byte>> read_cached_table(const std::string& name, size_t size);
// Stores `bytes` as `name`; best effort (returns false when the folder is off or unwritable).
bool write_cached_table(const std::string& name, std::span<const std::byte> bytes);

// A table of plain numbers (a trivially copyable T): the entry `name` when the folder has it,
// else make() stored as `name`.
template <class T, class Make>
T cached_table(const std::string& name, Make make) {
  static_assert(std::is_trivially_copyable_v<T>, "a table of plain numbers");
  if (std::optional<std::vector<std::byte>> bytes = read_cached_table(name, sizeof(T))) {
    T table;
    std::memcpy(&table, bytes->data(), sizeof(T));
    return table;
  }
  const T table = make();
  write_cached_table(name, std::as_bytes(std::span<const T>(&table, 1)));
  return table;
}

}  // namespace obscura
