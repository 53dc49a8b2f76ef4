// Writing an output file so that it either appears complete or not at all: the bytes go to a
// hidden temporary file beside the target, every write, the flush to disk and the close are
// checked (a full disk, a quota or a file-size limit is an error, never a truncated file), and
// only then is the temporary renamed over the target. On any failure the temporary file is
// removed and an existing target is left untouched. A replaced target's permission bits are
// kept.
#pragma once

#include <cstdint>
#include <span>
#include <string>

namespace obscura {

class AtomicFile {
 public:
  // Creates the temporary file beside `target`. Throws obscura::Error naming the target.
  explicit AtomicFile(std::string target);
  // Removes the temporary file unless commit() succeeded.
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  // Appends bytes. Throws obscura::Error naming the target and the system's reason (e.g. "No
  // space left on device"); the temporary file is removed then.
  void write(std::span<const uint8_t> bytes);
  void write(const std::string& text);
  // Flushes to disk, gives the file the replaced target's permission bits (if there is one),
  // closes it and renames it over the target. Throws obscura::Error, removing the temporary.
  void commit();

  const std::string& target() const { return target_; }
  const std::string& temporary() const { return temporary_; }

 private:
  [[noreturn]] void fail(const std::string& what);
  void discard();

  std::string target_;
  std::string temporary_;
  int fd_ = -1;
  bool committed_ = false;
};

// Writes `bytes` as the whole content of `path` through an AtomicFile.
void write_file_atomically(const std::string& path, std::span<const uint8_t> bytes);

}  // namespace obscura
