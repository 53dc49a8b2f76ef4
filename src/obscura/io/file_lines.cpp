#include "obscura/io/file_lines.h"

#include <cstring>

#include "obscura/io/mesh_file.h"
#include "obscura/math/error.h"

namespace obscura {

namespace {
constexpr size_t kChunkBytes = size_t(1) << 20;
}

FileLines::FileLines(const std::string& path) : path_(path) {
  check_mesh_file(path);
  in_.open(path, std::ios::binary);
  if (!in_) throw Error(path, "cannot open the file");
  buffer_.resize(kChunkBytes);
}

bool FileLines::refill() {
  // Keep the partial line at the front; a line longer than the buffer doubles it (bounded by the
  // file size cap, checked below).
  std::memmove(buffer_.data(), buffer_.data() + begin_, end_ - begin_);
  end_ -= begin_;
  begin_ = 0;
  if (end_ == buffer_.size()) buffer_.resize(buffer_.size() * 2);
  in_.read(buffer_.data() + end_, std::streamsize(buffer_.size() - end_));
  auto got = size_t(in_.gcount());
  if (in_.bad()) throw Error(path_, "cannot read the file");
  end_ += got;
  total_ += got;
  // A file that grows while it is read is not read past the cap.
  if (total_ > kMaxMeshFileBytes)
    throw Error(path_, "more than " + std::to_string(kMaxMeshFileBytes >> 20) +
                           " MiB; mesh files over that are not read");
  return got > 0;
}

bool FileLines::next(std::string_view& line) {
  while (true) {
    const char* start = buffer_.data() + begin_;
    const auto* newline = static_cast<const char*>(std::memchr(start, '\n', end_ - begin_));
    if (newline || eof_) {
      if (!newline && begin_ == end_) return false;
      size_t length = newline ? size_t(newline - start) : end_ - begin_;
      line = std::string_view(start, length);
      if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
      begin_ += length + (newline ? 1 : 0);
      ++line_number;
      return true;
    }
    if (!refill()) eof_ = true;
  }
}

}  // namespace obscura
