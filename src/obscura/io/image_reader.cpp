#include "obscura/io/image_reader.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <utility>

#include "obscura/io/exr_header_check.h"
#include "obscura/io/image_limits.h"
#include "obscura/math/error.h"

namespace obscura {

namespace {

std::string extension_for(const std::string& hint) {
  if (hint == "image/png") return "png";
  if (hint == "image/jpeg") return "jpg";
  if (hint.rfind("image/", 0) == 0) return hint.substr(6);
  return hint;
}

// Refuses, before anything is decoded, what the readers below cannot or must not decode.
void check_header(const OIIO::ImageSpec& spec, const std::string& source) {
  if (spec.deep) throw Error(source, "deep images are not supported; expected a flat image");
  check_decoded_size(source, spec.width, spec.height, spec.depth, spec.nchannels);
}

// OpenEXR allocates what its header declares before reading it: check the header first.
void check_exr_file(const std::string& path) {
  int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return;  // OpenImageIO reports why it cannot be read
  auto read = [fd](uint64_t offset, size_t size, uint8_t* out) {
    return ::pread(fd, out, size, off_t(offset)) == ssize_t(size);
  };
  uint8_t magic[4];
  try {
    if (read(0, 4, magic) && is_exr_magic(magic))
      check_exr_header(read, uint64_t(std::filesystem::file_size(path)), path);
  } catch (...) {
    ::close(fd);
    throw;
  }
  ::close(fd);
}

void check_exr_memory(std::span<const uint8_t> bytes, const std::string& source) {
  if (bytes.size() < 4 || !is_exr_magic(bytes.data())) return;
  auto read = [bytes](uint64_t offset, size_t size, uint8_t* out) {
    if (offset > bytes.size() || size > bytes.size() - offset) return false;
    std::memcpy(out, bytes.data() + offset, size);
    return true;
  };
  check_exr_header(read, bytes.size(), source);
}

}  // namespace

size_t BoundedMemoryReader::pread(void* buffer, size_t size, int64_t offset) {
  if (offset < 0 || uint64_t(offset) >= bytes_.size()) return 0;
  size_t n = std::min(size, bytes_.size() - size_t(offset));
  std::memcpy(buffer, bytes_.data() + offset, n);
  return n;
}

size_t BoundedMemoryReader::read(void* buffer, size_t size) {
  size_t n = pread(buffer, size, m_pos);
  m_pos += int64_t(n);
  return n;
}

CheckedImageInput::CheckedImageInput(std::string source,
                                     std::unique_ptr<BoundedMemoryReader> memory,
                                     std::unique_ptr<OIIO::ImageInput> input)
    : source_(std::move(source)), memory_(std::move(memory)), input_(std::move(input)) {
  check_header(input_->spec(), source_);
}

CheckedImageInput CheckedImageInput::open_file(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw Error(path, "image file does not exist");
  // A FIFO or a device such as /dev/zero would be read forever.
  if (!std::filesystem::is_regular_file(path, ec))
    throw Error(path, "not a regular file; expected an image file");
  check_exr_file(path);
  std::unique_ptr<OIIO::ImageInput> input = OIIO::ImageInput::open(path);
  if (!input) throw Error(path, "cannot read image: " + OIIO::geterror());
  return CheckedImageInput(path, nullptr, std::move(input));
}

CheckedImageInput CheckedImageInput::open_memory(std::span<const uint8_t> bytes,
                                                 const std::string& source,
                                                 const std::string& format_hint) {
  if (bytes.empty()) throw Error(source, "embedded image is empty");
  check_exr_memory(bytes, source);
  // OpenImageIO reads from memory through an IOProxy; the made-up file name only selects the
  // format reader.
  auto memory = std::make_unique<BoundedMemoryReader>(bytes);
  void* proxy = memory.get();
  OIIO::ImageSpec config;
  config.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);
  std::string ext = extension_for(format_hint);
  std::unique_ptr<OIIO::ImageInput> input =
      OIIO::ImageInput::open("embedded." + (ext.empty() ? std::string("png") : ext), &config);
  if (!input) throw Error(source, "cannot decode embedded image: " + OIIO::geterror());
  return CheckedImageInput(source, std::move(memory), std::move(input));
}

void CheckedImageInput::read(int channels, OIIO::TypeDesc type, void* pixels) {
  if (!input_->read_image(0, 0, 0, channels, type, pixels))
    throw Error(source_, "cannot decode image: " + input_->geterror());
}

}  // namespace obscura
