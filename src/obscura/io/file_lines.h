// The lines of a text file, read in chunks: a large OBJ is parsed without ever being held in
// memory whole (the buffer holds about a megabyte, or the longest line). Same interface as
// LineReader (mesh_file.h), which reads lines from bytes already in memory.
#pragma once

#include <fstream>
#include <string>
#include <string_view>
#include <vector>

namespace obscura {

class FileLines {
 public:
  // Opens `path` if it is a regular file of at most kMaxMeshFileBytes; else obscura::Error.
  explicit FileLines(const std::string& path);

  // The next line, without its '\n' or "\r\n"; valid until the next call. False at the end.
  bool next(std::string_view& line);

  size_t line_number = 0;  // of the line `next` returned last, from 1

 private:
  bool refill();

  std::string path_;
  std::ifstream in_;
  std::vector<char> buffer_;
  size_t begin_ = 0, end_ = 0;  // the unread bytes in buffer_
  uint64_t total_ = 0;          // bytes read so far
  bool eof_ = false;
};

}  // namespace obscura
