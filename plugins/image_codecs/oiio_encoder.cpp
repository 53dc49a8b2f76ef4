#include "oiio_encoder.h"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include "obscura/math/error.h"
#include "oiio_types.h"

namespace obscura::oiio {

namespace fs = std::filesystem;

namespace {

using WriteFn = std::function<bool(OIIO::ImageOutput&)>;

bool is_tiff(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return ext == ".tif" || ext == ".tiff";
}

// OpenImageIO 2.4's TIFF writer leaves out the image directory when it writes through an IOProxy
// (readers then fail with "TIFF directory is missing required ImageLength"), so a TIFF is encoded
// into a private temporary file instead, read back and removed. libtiff reports its errors
// through OpenImageIO, so nothing there ends the process.
std::vector<unsigned char> encode_through_temporary_file(const std::string& path,
                                                         const OIIO::ImageSpec& spec,
                                                         const WriteFn& write) {
  std::string pattern = (fs::temp_directory_path() / "obscura-encode-XXXXXX.tif").string();
  int fd = mkstemps(pattern.data(), 4);
  if (fd < 0) throw Error(path, "cannot create a temporary file to encode into");
  close(fd);
  struct Remove {
    std::string file;
    ~Remove() { std::remove(file.c_str()); }
  } remove{pattern};
  auto out = OIIO::ImageOutput::create(pattern);
  if (!out) throw Error(path, "no image writer: " + OIIO::geterror());
  errno = 0;
  bool ok = out->open(pattern, spec) && write(*out);
  int write_errno = errno;  // libtiff's messages leave out why a write failed
  std::string message = out->geterror();
  ok = out->close() && ok;
  if (!ok)
    throw Error(path,
                "cannot encode: " + message + out->geterror() +
                    (write_errno ? std::string(" (") + std::strerror(write_errno) + ")" : ""));
  std::ifstream in(pattern, std::ios::binary);
  std::vector<unsigned char> bytes{std::istreambuf_iterator<char>(in),
                                   std::istreambuf_iterator<char>()};
  if (!in.good() && !in.eof()) throw Error(path, "cannot read back the encoded image");
  return bytes;
}

// Encodes through a proxy into memory: the codecs never touch the output file, so a full disk
// cannot be ignored by a writer that does not check fwrite, nor end the process the way
// libjpeg's default error handler does (exit(1)); the caller writes the bytes atomically.
std::vector<unsigned char> encode_in_memory(const std::string& path, const OIIO::ImageSpec& spec,
                                            const WriteFn& write) {
  std::vector<unsigned char> encoded;
  OIIO::Filesystem::IOVecOutput memory(encoded);
  auto out = OIIO::ImageOutput::create(path, &memory);
  if (!out) throw Error(path, "no image writer: " + OIIO::geterror());
  if (!out->supports("ioproxy"))
    throw Error(path, "this OpenImageIO cannot encode the format into memory");
  if (!out->open(path, spec)) throw Error(path, "cannot encode: " + out->geterror());
  bool ok = write(*out);
  std::string message = out->geterror();
  ok = out->close() && ok;
  if (!ok) throw Error(path, "cannot encode: " + message + out->geterror());
  return encoded;
}

void add_attribute(OIIO::ImageSpec& spec, const HeaderAttribute& attribute) {
  if (const auto* text = std::get_if<std::string>(&attribute.value))
    spec.attribute(attribute.name, *text);
  else if (const auto* number = std::get_if<int>(&attribute.value))
    spec.attribute(attribute.name, *number);
  else if (const auto* floats = std::get_if<std::vector<float>>(&attribute.value))
    spec.attribute(attribute.name, OIIO::TypeDesc(OIIO::TypeDesc::FLOAT, int(floats->size())),
                   floats->data());
}

}  // namespace

std::vector<unsigned char> encode_image(const EncodeRequest& request) {
  OIIO::ImageSpec spec(request.width, request.height, request.channels, type_desc(request.stored));
  if (!request.channel_names.empty()) spec.channelnames = request.channel_names;
  for (const HeaderAttribute& attribute : request.attributes) add_attribute(spec, attribute);
  const WriteFn write = [&](OIIO::ImageOutput& out) {
    return out.write_image(type_desc(request.data_type), request.data);
  };
  if (is_tiff(request.path)) return encode_through_temporary_file(request.path, spec, write);
  return encode_in_memory(request.path, spec, write);
}

}  // namespace obscura::oiio
