// A text file, or text in memory, cut into blocks of whole lines (about half a megabyte each, or
// one line where a line is longer): what lets the OBJ reader parse blocks on several threads
// while a large file is never held in memory whole.
#pragma once

#include <fstream>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace obscura {

// One block: whole lines, each ending in '\n' except perhaps the file's last.
struct TextBlock {
  std::string_view text;  // into `storage`, or into the caller's bytes
  std::vector<char> storage;
};

class TextBlocks {
 public:
  // Reads `path` if it is a regular file of at most kMaxMeshFileBytes; else obscura::Error.
  explicit TextBlocks(const std::string& path);
  // Cuts `bytes` (kept by the caller while the blocks are used) without copying them.
  explicit TextBlocks(std::span<const char> bytes);

  // Fills `block` with the next lines; false at the end.
  bool next(TextBlock& block);

  static constexpr size_t kBlockBytes = size_t(1) << 19;

 private:
  bool next_from_file(TextBlock& block);

  std::string path_;  // empty for bytes in memory
  std::ifstream in_;
  std::vector<char> carry_;  // a partial line read past the last block's end
  std::string_view bytes_;   // what is left of the bytes in memory
  uint64_t total_ = 0;       // bytes read from the file so far
  bool eof_ = false;
};

}  // namespace obscura
