#include "obscura/io/text_blocks.h"

#include <cstring>

#include "obscura/io/mesh_file.h"
#include "obscura/math/error.h"

namespace obscura {

namespace {

// The length of `text` up to and including its last '\n' (0 if it has none), from `from` on.
size_t whole_lines(std::string_view text, size_t from) {
  for (size_t i = text.size(); i > from; --i)
    if (text[i - 1] == '\n') return i;
  return 0;
}

}  // namespace

TextBlocks::TextBlocks(const std::string& path) : path_(path) {
  check_mesh_file(path);
  in_.open(path, std::ios::binary);
  if (!in_) throw Error(path, "cannot open the file");
}

TextBlocks::TextBlocks(std::span<const char> bytes) : bytes_(bytes.data(), bytes.size()) {}

bool TextBlocks::next(TextBlock& block) {
  block.storage.clear();
  if (!path_.empty()) return next_from_file(block);
  if (bytes_.empty()) return false;
  size_t size = std::min(bytes_.size(), kBlockBytes);
  if (size < bytes_.size()) {
    // Up to the last newline within the block size, or else up to the first after it.
    size_t cut = whole_lines(bytes_.substr(0, size), 0);
    if (cut == 0) {
      size_t newline = bytes_.find('\n', size);
      cut = newline == std::string_view::npos ? bytes_.size() : newline + 1;
    }
    size = cut;
  }
  block.text = bytes_.substr(0, size);
  bytes_.remove_prefix(size);
  return true;
}

bool TextBlocks::next_from_file(TextBlock& block) {
  std::vector<char>& buffer = block.storage;
  buffer = std::move(carry_);
  carry_.clear();
  size_t searched = 0;  // bytes of `buffer` known to hold no newline
  while (!eof_) {
    size_t have = buffer.size();
    buffer.resize(have + kBlockBytes);
    in_.read(buffer.data() + have, std::streamsize(kBlockBytes));
    auto got = size_t(in_.gcount());
    if (in_.bad()) throw Error(path_, "cannot read the file");
    buffer.resize(have + got);
    total_ += got;
    // A file that grows while it is read is not read past the cap.
    if (total_ > kMaxMeshFileBytes)
      throw Error(path_, "more than " + std::to_string(kMaxMeshFileBytes >> 20) +
                             " MiB; mesh files over that are not read");
    if (got == 0) eof_ = true;
    size_t cut = whole_lines(std::string_view(buffer.data(), buffer.size()), searched);
    if (cut > 0) {
      carry_.assign(buffer.begin() + std::ptrdiff_t(cut), buffer.end());
      buffer.resize(cut);
      break;
    }
    searched = buffer.size();  // a line longer than a block: read on to its end
  }
  if (buffer.empty()) return false;
  block.text = std::string_view(buffer.data(), buffer.size());
  return true;
}

}  // namespace obscura
