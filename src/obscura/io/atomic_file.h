// Writing an output file so that it either appears complete or not at all: the bytes go to a
// hidden temporary file beside the target, every write, the flush to disk and the close are
// checked (a full disk, a quota or a file-size limit is an error, never a truncated file), and
// only then is the temporary renamed over the target. On any failure the temporary file is
// removed and an existing target is left untouched. A replaced target's permission bits are
// kept. Only a regular file is ever replaced: a path that names a device, a FIFO, a socket or
// a directory (directly or through a symbolic link) is refused, so that `-o /dev/stdout` or a
// FIFO is never turned into a regular file.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

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

// Several outputs committed together (a frame and its ground truth): while a transaction lives,
// AtomicFile::commit() on its thread finishes the file (written, flushed, closed) but leaves the
// rename to the transaction's commit(), which moves every finished file into place. A
// transaction destroyed uncommitted (an exception, a cancel) removes them all, so either every
// output is replaced or none is.
class OutputTransaction {
 public:
  OutputTransaction();
  ~OutputTransaction();
  OutputTransaction(const OutputTransaction&) = delete;
  OutputTransaction& operator=(const OutputTransaction&) = delete;

  // Renames every finished file over its target, in the order they were finished. Throws
  // obscura::Error naming the target that could not be moved; the ones not yet moved are removed.
  void commit();

 private:
  friend class AtomicFile;
  struct Finished {
    std::string temporary, target;
  };
  std::vector<Finished> finished_;
  OutputTransaction* outer_;
};

// Throws obscura::RequestError naming `target` and what it is when it exists and is not a
// regular file (a symbolic link is followed): outputs replace regular files or create new ones.
void check_replaceable_output(const std::string& target);

// Writes `bytes` as the whole content of `path` through an AtomicFile.
void write_file_atomically(const std::string& path, std::span<const uint8_t> bytes);

}  // namespace obscura
