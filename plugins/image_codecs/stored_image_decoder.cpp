#include "stored_image_decoder.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "obscura/math/error.h"
#include "sample_conversion.h"

namespace obscura::codecs {

EncodedBytes read_encoded_file(const std::string& path, const std::string& source) {
  EncodedBytes encoded;
  encoded.source = source;
  int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw Error(source, std::string("cannot open: ") + std::strerror(errno));
  struct stat st {};
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    ::close(fd);
    throw Error(source, "not a regular file; expected an image file");
  }
  const size_t size = size_t(st.st_size);
  void* address = size ? ::mmap(nullptr, size, PROT_READ, MAP_PRIVATE, fd, 0) : nullptr;
  const int map_errno = errno;
  ::close(fd);  // the mapping keeps the file
  if (address == MAP_FAILED)
    throw Error(source, std::string("cannot map the file: ") + std::strerror(map_errno));
  if (address) {
    encoded.mapping = std::shared_ptr<const void>(
        address, [size](const void* p) { ::munmap(const_cast<void*>(p), size); });
    encoded.bytes = {static_cast<const uint8_t*>(address), size};
  }
  return encoded;
}

EncodedBytes borrow_encoded_bytes(std::span<const uint8_t> bytes, const std::string& source) {
  EncodedBytes encoded;
  encoded.bytes = bytes;
  encoded.source = source;
  return encoded;
}

void StoredImageDecoder::read(int channels, SampleType type, void* pixels) {
  if (channels < 1 || channels > header_.channels || type == SampleType::kOther)
    throw Error(header_.format_name + " decoder: cannot read " + std::to_string(channels) +
                " channels of " + std::to_string(header_.channels));
  if (channels == header_.channels && type == header_.format) return decode_stored(pixels);
  const size_t pixel_count = size_t(header_.width) * size_t(header_.height);
  std::vector<unsigned char> stored(pixel_count * size_t(header_.channels) *
                                    sample_size(header_.format));
  decode_stored(stored.data());
  convert_pixels(header_.format, stored.data(), header_.channels, type, pixels, channels,
                 pixel_count);
}

std::vector<std::string> default_channel_names(int channels) {
  switch (channels) {
    case 1:
      return {"Y"};
    case 2:
      return {"Y", "A"};
    case 3:
      return {"R", "G", "B"};
    case 4:
      return {"R", "G", "B", "A"};
    default:
      break;
  }
  std::vector<std::string> names;
  for (int c = 0; c < channels; ++c) names.push_back("channel" + std::to_string(c));
  return names;
}

}  // namespace obscura::codecs
