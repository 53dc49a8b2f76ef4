#include "obscura/io/image_io.h"

#include <unistd.h>

#include <algorithm>
#include <bit>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <system_error>
#include <vector>

#include <OpenImageIO/imageio.h>

#include "obscura/color/srgb.h"
#include "obscura/math/error.h"

namespace obscura {

namespace fs = std::filesystem;

namespace {

std::string lowercase_extension(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

// A name in the target's directory, hidden, unique to this process.
fs::path temporary_path_for(const fs::path& target) {
  // (Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on `"." + std::string`.)
  std::string name(1, '.');
  name.append(target.filename().string()).append(".tmp-").append(std::to_string(getpid()));
  return target.parent_path() / name;
}

std::vector<uint8_t> encode_srgb_8bit(const Image& image) {
  std::vector<uint8_t> out(image.data.size());
  for (size_t i = 0; i < image.data.size(); ++i) {
    bool is_alpha = image.channels == 4 && i % 4 == 3;
    float v = image.data[i];
    if (!std::isfinite(v)) v = 0;  // NaN/Inf never reach the file as garbage
    float e = is_alpha ? v : srgb_encode(v);
    out[i] = uint8_t(std::lround(std::clamp(e, 0.f, 1.f) * 255.f));
  }
  return out;
}

// PFM (Portable Float Map): "PF" (RGB) or "Pf" (grey), the size, a scale whose negative sign
// means little-endian, then rows of 32-bit floats from the bottom of the image to the top.
// OpenImageIO 2.4 reads PFM but has no writer for it, so it is written here.
bool write_pfm(const fs::path& file, const Image& image) {
  std::FILE* f = std::fopen(file.c_str(), "wb");
  if (!f) return false;
  std::fprintf(f, "PF\n%d %d\n-1.0\n", image.width, image.height);
  std::vector<float> row(size_t(image.width) * 3);
  bool ok = true;
  for (int y = image.height - 1; y >= 0 && ok; --y) {
    for (int x = 0; x < image.width; ++x)
      for (int c = 0; c < 3; ++c) row[size_t(x) * 3 + c] = image.at(x, y, c);  // drops alpha
    ok = std::fwrite(row.data(), sizeof(float), row.size(), f) == row.size();
  }
  return std::fclose(f) == 0 && ok;
}

static_assert(std::endian::native == std::endian::little, "the PFM writer assumes little-endian");

}  // namespace

ImageFormat image_format_for_path(const std::string& path) {
  std::string ext = lowercase_extension(path);
  if (ext == ".png") return ImageFormat::kPng;
  if (ext == ".exr") return ImageFormat::kExr;
  if (ext == ".pfm") return ImageFormat::kPfm;
  throw Error(path, "unsupported image extension '" + ext + "'; expected .png, .exr or .pfm");
}

void check_output_path(const std::string& path) {
  if (path.empty()) throw Error("output path is empty");
  fs::path target(path);
  std::error_code ec;
  if (fs::is_directory(target, ec))
    throw Error(path, "output path is a directory; expected a file name such as " +
                          (target / "render.png").string());
  image_format_for_path(path);
  fs::path parent = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  if (!fs::is_directory(parent, ec))
    throw Error(path, "output directory '" + parent.string() + "' does not exist");
  if (access(parent.c_str(), W_OK) != 0)
    throw Error(path, "output directory '" + parent.string() + "' is not writable");
  if (fs::exists(target, ec) && access(target.c_str(), W_OK) != 0)
    throw Error(path, "output file exists and is not writable");
}

void write_image(const std::string& path, const Image& image) {
  if (image.width <= 0 || image.height <= 0 || (image.channels != 3 && image.channels != 4))
    throw Error(path, "cannot write an image of " + std::to_string(image.width) + "x" +
                          std::to_string(image.height) + "x" + std::to_string(image.channels) +
                          "; expected a non-empty RGB or RGBA image");
  check_output_path(path);
  ImageFormat format = image_format_for_path(path);
  fs::path tmp = temporary_path_for(path);
  auto fail = [&](const std::string& what) {
    std::error_code ignored;
    fs::remove(tmp, ignored);
    throw Error(path, what);
  };
  auto move_into_place = [&] {
    std::error_code ec;
    fs::rename(tmp, path, ec);
    if (ec) fail("cannot move the finished file into place: " + ec.message());
  };

  if (format == ImageFormat::kPfm) {
    if (!write_pfm(tmp, image)) fail("cannot write: " + std::string(std::strerror(errno)));
    move_into_place();
    return;
  }

  auto out = OIIO::ImageOutput::create(path);
  if (!out) throw Error(path, "no image writer: " + OIIO::geterror());
  OIIO::TypeDesc type =
      format == ImageFormat::kPng ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT;
  OIIO::ImageSpec spec(image.width, image.height, image.channels, type);
  if (!image.channel_names.empty()) spec.channelnames = image.channel_names;
  spec.attribute("oiio:ColorSpace", format == ImageFormat::kPng ? "sRGB" : "Linear");
  spec.attribute("Software", "Obscura " OBSCURA_VERSION);

  if (!out->open(tmp.string(), spec)) fail("cannot open for writing: " + out->geterror());
  bool ok;
  if (format == ImageFormat::kPng) {
    std::vector<uint8_t> bytes = encode_srgb_8bit(image);
    ok = out->write_image(OIIO::TypeDesc::UINT8, bytes.data());
  } else {
    ok = out->write_image(OIIO::TypeDesc::FLOAT, image.data.data());
  }
  if (!ok) {
    std::string message = out->geterror();
    out->close();
    fail("write failed: " + message);
  }
  if (!out->close()) fail("write failed: " + out->geterror());
  move_into_place();
}

Image read_image(const std::string& path) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) throw Error(path, "cannot read image: " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  Image image(spec.width, spec.height, spec.nchannels);
  image.channel_names = spec.channelnames;
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, image.data.data()))
    throw Error(path, "cannot decode image: " + in->geterror());
  in->close();
  return image;
}

}  // namespace obscura
