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

// The OpenImageIO reader for an image whose leading bytes identify it, or "" when they do not.
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

// Opens `name` with `reader`; `proxy`, when given, supplies the bytes.
std::unique_ptr<OIIO::ImageInput> open_with(const std::string& reader, const std::string& name,
                                            BoundedMemoryReader* proxy, const std::string& source) {
  // OpenImageIO 2.4's TIFF reader decompresses zip strips on its thread pool and, when a strip
  // read fails, returns before those tasks finish: they go on reading its freed scratch buffer
  // and writing into the caller's pixels after the read has failed (a published advisory, fixed
  // upstream in 3.1.16; the image fuzz target met it as heap corruption in a freed block).
  // Decompressing on the calling thread closes it, at the cost of parallel decompression of zip
  // TIFFs.
  static const bool tiff_serial = OIIO::attribute("tiff:multithread", 0);
  (void)tiff_serial;
  OIIO::ImageSpec config;
  if (proxy) {
    void* p = proxy;
    config.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &p);
  }
  // Colour as stored, never multiplied by alpha: OpenImageIO premultiplies the straight alpha of
  // PNG, Targa and the like by default, which darkened every partly transparent texel of a glTF
  // texture (whose alpha is straight by the specification) — by 2× on AlphaBlendModeTest's
  // cutoff panels, against Cycles. Files that store premultiplied colour (OpenEXR) keep it.
  config.attribute("oiio:UnassociatedAlpha", 1);
  // create() with do_open = false picks the reader by name and never falls back to others.
  std::unique_ptr<OIIO::ImageInput> input = OIIO::ImageInput::create(reader, false, &config);
  if (!input) throw Error(source, "cannot read image: " + OIIO::geterror());
  OIIO::ImageSpec spec;
  bool opened = input->open(name, spec, config);
  if (!opened) {
    std::string why = input->geterror();
    if (why.empty()) why = OIIO::geterror();
    throw Error(source, "cannot read image as " + reader + (why.empty() ? "" : ": " + why));
  }
  return input;
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
  std::string ext = std::filesystem::path(path).extension().string();
  std::string reader = reader_for(read_head(path), ext.empty() ? ext : ext.substr(1), path);
  return CheckedImageInput(path, nullptr, open_with(reader, path, nullptr, path));
}

CheckedImageInput CheckedImageInput::open_memory(std::span<const uint8_t> bytes,
                                                 const std::string& source,
                                                 const std::string& format_hint) {
  if (bytes.empty()) throw Error(source, "embedded image is empty");
  check_exr_memory(bytes, source);
  // OpenImageIO reads from memory through an IOProxy; the made-up file name is only a name.
  auto memory = std::make_unique<BoundedMemoryReader>(bytes);
  std::string reader = reader_for(bytes.first(std::min<size_t>(bytes.size(), 16)),
                                  extension_for(format_hint), source);
  std::unique_ptr<OIIO::ImageInput> input =
      open_with(reader, "embedded." + reader, memory.get(), source);
  return CheckedImageInput(source, std::move(memory), std::move(input));
}

void CheckedImageInput::read(int channels, OIIO::TypeDesc type, void* pixels) {
  const OIIO::ImageSpec& spec = input_->spec();
  // OpenImageIO 2.4 reads a scanline image through a buffer of 64 MiB, whatever the image's size
  // (every 4 × 4 texture allocated it), unless the read asks for TypeDesc::UNKNOWN — the file's
  // own types — even when the type asked is the file's. So: read that way, into a buffer of the
  // image's size, and convert here.
  auto read_native = [&](void* out) {
    if (!input_->read_image(0, 0, 0, channels, OIIO::TypeDesc::UNKNOWN, out))
      throw Error(source_, "cannot decode image: " + input_->geterror());
  };
  auto unconvertible = [&](OIIO::TypeDesc from) {
    return Error(source_, "cannot convert the image's " + std::string(from.c_str()) +
                              " values to " + type.c_str());
  };
  if (spec.channelformats.empty() && spec.format == type) return read_native(pixels);
  size_t pixel_count = size_t(spec.width) * size_t(spec.height);
  size_t native_pixel_bytes = spec.pixel_bytes(0, channels, true);
  std::vector<std::byte> native(pixel_count * native_pixel_bytes);
  read_native(native.data());
  auto* out = static_cast<std::byte*>(pixels);
  if (spec.channelformats.empty()) {
    // In pieces: the count is an int, and a raised pixel limit may pass more values than it holds.
    size_t values = pixel_count * size_t(channels);
    constexpr size_t kPiece = size_t(1) << 24;
    for (size_t first = 0; first < values; first += kPiece) {
      int n = int(std::min(kPiece, values - first));
      if (!OIIO::convert_pixel_values(spec.format, native.data() + first * spec.format.size(), type,
                                      out + first * type.size(), n))
        throw unconvertible(spec.format);
    }
    return;
  }
  // Channels stored in different types (an OpenEXR with half colour and float depth): one
  // channel at a time, each from its own type.
  size_t offset = 0;
  OIIO::stride_t out_pixel_bytes = OIIO::stride_t(channels) * OIIO::stride_t(type.size());
  for (int c = 0; c < channels; ++c) {
    OIIO::TypeDesc from = spec.channelformats[size_t(c)];
    if (!OIIO::convert_image(1, spec.width, spec.height, 1, native.data() + offset, from,
                             OIIO::stride_t(native_pixel_bytes),
                             OIIO::stride_t(native_pixel_bytes) * spec.width, OIIO::AutoStride,
                             out + size_t(c) * type.size(), type, out_pixel_bytes,
                             out_pixel_bytes * spec.width, OIIO::AutoStride))
      throw unconvertible(from);
    offset += from.size();
  }
}

}  // namespace obscura
