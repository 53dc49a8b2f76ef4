#include "obscura/io/image_reader.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstddef>
#include <cstring>
#include <filesystem>
#include <string_view>
#include <utility>
#include <vector>

#include "obscura/io/exr_header_check.h"
#include "obscura/io/image_codecs_loader.h"
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

std::string lowercase(std::string s) {
  for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// The reader (by OpenImageIO's names for them) for an image whose leading bytes identify it, or ""
// when they do not.
std::string reader_for_magic(std::span<const uint8_t> head) {
  auto starts = [head](std::string_view magic, size_t at = 0) {
    return head.size() >= at + magic.size() &&
           std::memcmp(head.data() + at, magic.data(), magic.size()) == 0;
  };
  using namespace std::string_view_literals;
  if (starts("\x89PNG\r\n\x1a\n"sv)) return "png";
  if (starts("\xff\xd8\xff"sv)) return "jpeg";
  if (starts("\x76\x2f\x31\x01"sv)) return "openexr";
  if (starts("#?"sv)) return "hdr";  // #?RADIANCE, #?RGBE
  if (starts("II*\0"sv) || starts("MM\0*"sv) || starts("II+\0"sv) || starts("MM\0+"sv))
    return "tiff";
  if (starts("BM"sv)) return "bmp";
  // PFM (PF, Pf) and the netpbm family (P1–P6), followed by white space.
  if (head.size() >= 3 && head[0] == 'P' &&
      (head[1] == 'F' || head[1] == 'f' || (head[1] >= '1' && head[1] <= '6')) &&
      std::isspace(head[2]))
    return "pnm";
  return "";
}

// Chooses the one reader that may decode an image: the format its bytes announce, or — for
// Targa, the one readable format without a signature — its extension. OpenImageIO's own
// ImageInput::open, when the first reader refuses a file, hands it to every reader it has
// (camera raw, video, DICOM, GIS, volumes): for a hostile or corrupt file that is some thirty
// more parsers exposed to it, and a few milliseconds of their set-up for nothing. (GIF and WebP
// are left out on purpose: OpenImageIO 2.4's readers for them allocate and decode the whole
// canvas the header declares — up to 65535² for GIF — inside open(), before the size check
// here can refuse it.)
std::string reader_for(std::span<const uint8_t> head, const std::string& extension,
                       const std::string& source) {
  std::string reader = reader_for_magic(head);
  if (!reader.empty()) return reader;
  std::string ext = lowercase(extension);
  if (ext == "tga" || ext == "tpic" || ext == "targa") return "targa";
  throw Error(source,
              "not a readable image: the first bytes are not those of a PNG, JPEG, OpenEXR, "
              "Radiance HDR, PFM/PNM, TIFF or BMP file (nor is it a .tga)");
}

// Refuses, before anything is decoded, what the readers below cannot or must not decode.
void check_header(const ImageHeader& header, const std::string& source) {
  if (header.deep) throw Error(source, "deep images are not supported; expected a flat image");
  check_decoded_size(source, header.width, header.height, header.depth, header.channels);
}

// OpenEXR allocates what its header declares before reading it: check the header first.
void check_exr_file(const std::string& path) {
  int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return;  // the codecs report why it cannot be read
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

// The first bytes of a file, which say what it is (fewer when it is shorter).
std::vector<uint8_t> read_head(const std::string& path) {
  std::vector<uint8_t> head(16);
  int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw Error(path, std::string("cannot open: ") + std::strerror(errno));
  ssize_t n = ::pread(fd, head.data(), head.size(), 0);
  ::close(fd);
  head.resize(size_t(std::max<ssize_t>(n, 0)));
  return head;
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

CheckedImageInput::CheckedImageInput(std::string source, std::unique_ptr<ImageDecoder> decoder)
    : source_(std::move(source)), decoder_(std::move(decoder)) {
  check_header(decoder_->header(), source_);
}

CheckedImageInput CheckedImageInput::open_file(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw Error(path, "image file does not exist");
  // A FIFO or a device such as /dev/zero would be read forever.
  if (!std::filesystem::is_regular_file(path, ec))
    throw Error(path, "not a regular file; expected an image file");
  check_exr_file(path);
  std::string ext = std::filesystem::path(path).extension().string();
  std::string reader = reader_for(read_head(path), ext.empty() ? ext : ext.substr(1), path);
  return CheckedImageInput(path, image_codecs().open(reader, path, false, {}, path));
}

CheckedImageInput CheckedImageInput::open_memory(std::span<const uint8_t> bytes,
                                                 const std::string& source,
                                                 const std::string& format_hint) {
  if (bytes.empty()) throw Error(source, "embedded image is empty");
  check_exr_memory(bytes, source);
  std::string reader = reader_for(bytes.first(std::min<size_t>(bytes.size(), 16)),
                                  extension_for(format_hint), source);
  // The made-up file name is only a name: the codecs read `bytes`.
  return CheckedImageInput(source,
                           image_codecs().open(reader, "embedded." + reader, true, bytes, source));
}

}  // namespace obscura
