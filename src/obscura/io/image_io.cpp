#include "obscura/io/image_io.h"

#include <unistd.h>

#include <algorithm>
#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <system_error>
#include <vector>

#include "obscura/color/quantize.h"
#include "obscura/io/atomic_file.h"
#include "obscura/io/image_codecs_loader.h"
#include "obscura/io/image_reader.h"
#include "obscura/io/y4m_writer.h"
#include "obscura/math/error.h"
#include "obscura/math/request_error.h"

namespace obscura {

namespace fs = std::filesystem;

namespace {

std::string lowercase_extension(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  return ext;
}

// Encodes through the image codecs plugin, which returns the file's bytes, and only then writes
// them through an AtomicFile, whose every write is checked.
void write_encoded(const EncodeRequest& request) {
  write_file_atomically(request.path, image_codecs().encode(request));
}

// Linear values with NaN/Inf replaced by defined ones (and counted).
std::vector<float> sanitized(const Image& image, float largest, DevelopStats& stats) {
  std::vector<float> data = image.data;
  for (size_t p = 0; p < data.size(); p += image.channels) {
    bool nan = false, inf = false;
    for (int c = 0; c < image.channels; ++c) {
      float& v = data[p + c];
      if (std::isnan(v))
        nan = true, v = 0;
      else if (std::isinf(v))
        inf = true, v = 0;
      else if (v > largest)
        v = largest;
    }
    if (nan)
      stats.nan_pixels++;
    else if (inf)
      stats.inf_pixels++;
  }
  return data;
}

void add_metadata(std::vector<HeaderAttribute>& attributes, const ImageMetadata& metadata) {
  if (!metadata.description.empty())
    attributes.push_back({"ImageDescription", metadata.description});
  for (const auto& [name, value] : metadata.attributes) attributes.push_back({name, value});
}

EncodeRequest encode_request(const std::string& path, int width, int height, int channels,
                             SampleType stored) {
  EncodeRequest request;
  request.path = path;
  request.width = width;
  request.height = height;
  request.channels = channels;
  request.stored = stored;
  return request;
}

std::string colorspace_attribute(DisplaySpace d) {
  switch (d) {
    case DisplaySpace::kSrgb:
      return "sRGB";
    case DisplaySpace::kDisplayP3:
      return "Display P3";
    case DisplaySpace::kRec2020Pq:
      return "Rec2100-PQ";
    case DisplaySpace::kRec2020Hlg:
      return "Rec2100-HLG";
  }
  return "sRGB";
}

// Portable float map, encoded directly (OpenImageIO 2.4, which reads PFM, has no writer for it):
// "PF" (RGB) or "Pf" (grey), width and height, a negative scale meaning little-endian, then rows
// bottom to top.
std::vector<uint8_t> encode_pfm(int width, int height, int channels,
                                const std::vector<float>& data) {
  static_assert(std::endian::native == std::endian::little, "PFM is written little-endian");
  std::string header = std::string(channels == 1 ? "Pf" : "PF") + "\n" + std::to_string(width) +
                       " " + std::to_string(height) + "\n-1.0\n";
  size_t row = size_t(width) * channels * sizeof(float);
  std::vector<uint8_t> bytes(header.begin(), header.end());
  bytes.reserve(header.size() + row * height);
  for (int y = height - 1; y >= 0; --y) {
    auto first = reinterpret_cast<const uint8_t*>(data.data() + size_t(y) * width * channels);
    bytes.insert(bytes.end(), first, first + row);
  }
  return bytes;
}

WriteReport write_linear(const std::string& path, ImageFormat format, const Image& image,
                         const ImageWriteOptions& options) {
  WriteReport report;
  bool half = format == ImageFormat::kExr && options.exr_half;
  float largest = half ? 65504.f : FLT_MAX;
  std::vector<float> data = sanitized(image, largest, report.stats);
  int channels = image.channels;
  if ((format == ImageFormat::kHdr || (format == ImageFormat::kPfm && channels == 4)) &&
      channels != 3) {  // RGBE holds RGB only; PFM grey or RGB
    std::vector<float> rgb(size_t(image.width) * image.height * 3);
    for (size_t p = 0; p < rgb.size() / 3; ++p)
      for (int c = 0; c < 3; ++c) rgb[3 * p + c] = data[p * channels + (channels == 1 ? 0 : c)];
    data.swap(rgb);
    channels = 3;
  }
  if (format == ImageFormat::kPfm) {
    write_file_atomically(path, encode_pfm(image.width, image.height, channels, data));
    return report;
  }
  EncodeRequest request = encode_request(path, image.width, image.height, channels,
                                         half ? SampleType::kHalf : SampleType::kFloat);
  if (!image.channel_names.empty() && channels == image.channels)
    request.channel_names = image.channel_names;
  request.attributes.push_back({"oiio:ColorSpace", std::string("Linear")});
  request.attributes.push_back({"Software", std::string("Obscura " OBSCURA_VERSION)});
  add_metadata(request.attributes, options.metadata);
  if (format == ImageFormat::kExr) {
    // The film's working space: Rec.709 primaries, D65 white (x, y of R, G, B, white).
    request.attributes.push_back(
        {"chromaticities",
         std::vector<float>{0.64f, 0.33f, 0.30f, 0.60f, 0.15f, 0.06f, 0.3127f, 0.3290f}});
    request.attributes.push_back({"compression", std::string("zip")});
  }
  request.data_type = SampleType::kFloat;
  request.data = data.data();
  write_encoded(request);
  return report;
}

}  // namespace

ImageFormat image_format_for_path(const std::string& path) {
  std::string ext = lowercase_extension(path);
  if (ext == ".png") return ImageFormat::kPng;
  if (ext == ".jpg" || ext == ".jpeg") return ImageFormat::kJpeg;
  if (ext == ".tif" || ext == ".tiff") return ImageFormat::kTiff;
  if (ext == ".exr") return ImageFormat::kExr;
  if (ext == ".hdr") return ImageFormat::kHdr;
  if (ext == ".pfm") return ImageFormat::kPfm;
  if (ext == ".y4m") return ImageFormat::kY4m;
  if (ext == ".dng") return ImageFormat::kDng;
  throw Error(path, "unsupported image extension '" + ext +
                        "'; expected .png, .jpg, .tif, .exr, .hdr, .pfm, .y4m or .dng");
}

bool format_keeps_metadata(ImageFormat f) {
  return f != ImageFormat::kHdr && f != ImageFormat::kPfm;
}

bool is_display_format(ImageFormat f) {
  return f == ImageFormat::kPng || f == ImageFormat::kJpeg || f == ImageFormat::kTiff ||
         f == ImageFormat::kY4m;
}

void check_not_an_input(const std::string& output, const std::vector<std::string>& inputs) {
  std::error_code ec;
  for (const std::string& input : inputs)
    if (fs::exists(output, ec) && fs::equivalent(output, input, ec))
      throw Error(output, "output is the input file '" + input +
                              "'; refusing to overwrite an input, choose another output path");
}

void check_output_path(const std::string& path, const std::string& option) {
  if (path.empty()) throw Error("output path is empty");
  fs::path target(path);
  std::error_code ec;
  if (fs::is_directory(target, ec))
    throw Error(path, "output path is a directory; expected a file name such as " +
                          (target / "render.png").string());
  try {
    check_replaceable_output(path);
  } catch (const RequestError& e) {
    if (option.empty()) throw;
    throw RequestError(option + " " + e.what());
  }
  ImageFormat format = image_format_for_path(path);
  fs::path parent = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  if (!fs::is_directory(parent, ec))
    throw Error(path, "output directory '" + parent.string() + "' does not exist");
  if (access(parent.c_str(), W_OK) != 0)
    throw Error(path, "output directory '" + parent.string() + "' is not writable");
  if (fs::exists(target, ec) && access(target.c_str(), W_OK) != 0)
    throw Error(path, "output file exists and is not writable");
  // The codecs are loaded now, so that a missing plugin stops a command before its work, not
  // after (PFM and Y4M are written without them).
  if (format != ImageFormat::kPfm && format != ImageFormat::kY4m) {
    try {
      image_codecs();
    } catch (const Error& e) {
      throw Error(path, e.what());
    }
  }
}

void write_display_image(const std::string& path, const DisplayImage& image,
                         const ImageMetadata& metadata) {
  check_output_path(path);
  ImageFormat format = image_format_for_path(path);
  if (format == ImageFormat::kY4m) {
    Y4mSettings settings;
    for (const auto& [name, value] : metadata.attributes)
      settings.header_tags.push_back(y4m_tag(name, value));
    Y4mWriter writer(path, image.width, image.height, settings);
    writer.write_frame(image);
    writer.close();
    return;
  }
  if (!is_display_format(format))
    throw Error(path,
                "developed codes go to .png, .jpg, .tif or .y4m; linear formats take the "
                "film image itself");
  // Container depth: 8 bits up to 8 (JPEG: always 8), else 16; codes of fewer bits are spread
  // over the container's range exactly (q·(2ᴹ−1)/(2ᴺ−1), rounded), so 5-bit banding stays visible.
  int container = image.bits <= 8 || format == ImageFormat::kJpeg ? 8 : 16;
  EncodeRequest request = encode_request(path, image.width, image.height, image.channels,
                                         container == 8 ? SampleType::kUint8 : SampleType::kUint16);
  request.attributes.push_back({"oiio:ColorSpace", colorspace_attribute(image.display)});
  request.attributes.push_back(
      {"obscura:display", std::string(display_space_info(image.display).name)});
  request.attributes.push_back({"obscura:bits", image.bits});
  request.attributes.push_back({"Software", std::string("Obscura " OBSCURA_VERSION)});
  if (format == ImageFormat::kJpeg)
    request.attributes.push_back({"Compression", std::string("jpeg:95")});
  add_metadata(request.attributes, metadata);
  std::vector<uint16_t> codes(image.codes.size());
  for (size_t i = 0; i < codes.size(); ++i)
    codes[i] =
        uint16_t(image.bits == container ? image.codes[i]
                                         : requantize(image.codes[i], image.bits, container));
  std::vector<uint8_t> bytes;
  if (container == 16) {
    request.data_type = SampleType::kUint16;
    request.data = codes.data();
  } else {
    bytes.assign(codes.begin(), codes.end());
    request.data_type = SampleType::kUint8;
    request.data = bytes.data();
  }
  write_encoded(request);
}

WriteReport write_image(const std::string& path, const Image& image,
                        const ImageWriteOptions& options) {
  if (image.width <= 0 || image.height <= 0 ||
      (image.channels != 1 && image.channels != 3 && image.channels != 4))
    throw Error(path, "cannot write an image of " + std::to_string(image.width) + "x" +
                          std::to_string(image.height) + "x" + std::to_string(image.channels) +
                          "; expected a non-empty grey, RGB or RGBA image");
  check_output_path(path);
  ImageFormat format = image_format_for_path(path);
  if (format == ImageFormat::kDng)
    throw Error(path,
                "a DNG holds a raw sensor's data, not a rendered image: render with a sensor "
                "(--raw-sensor, a camera's \"sensor\" block) to write one");
  if (!is_display_format(format)) return write_linear(path, format, image, options);
  ImageWriteOptions o = options;
  if (format == ImageFormat::kJpeg || format == ImageFormat::kY4m)
    o.display.bits = std::min(o.display.bits, 8);
  DisplayImage developed = develop(pixels_of(image), o.display);
  write_display_image(path, developed, options.metadata);
  return {developed.stats};
}

void write_exr_data(const std::string& path, const Image& image, const ImageMetadata& metadata) {
  if (image.width <= 0 || image.height <= 0 || image.channels <= 0 ||
      image.channel_names.size() != size_t(image.channels) ||
      image.data.size() != size_t(image.width) * image.height * image.channels)
    throw Error(path, "cannot write " + std::to_string(image.width) + "x" +
                          std::to_string(image.height) + "x" + std::to_string(image.channels) +
                          " data: expected a non-empty image with a name for every channel");
  if (image_format_for_path(path) != ImageFormat::kExr)
    throw Error(path, "data files are OpenEXR: the name must end in .exr");
  check_output_path(path);
  EncodeRequest request =
      encode_request(path, image.width, image.height, image.channels, SampleType::kFloat);
  request.channel_names = image.channel_names;
  request.attributes.push_back({"Software", std::string("Obscura " OBSCURA_VERSION)});
  request.attributes.push_back({"compression", std::string("zip")});
  add_metadata(request.attributes, metadata);
  request.data_type = SampleType::kFloat;
  request.data = image.data.data();
  write_encoded(request);
}

Image read_exr_data(const std::string& path, ImageMetadata& metadata) {
  CheckedImageInput in = CheckedImageInput::open_file(path);
  const ImageHeader& header = in.header();
  if (in.format_name() != "openexr")
    throw Error(path, "not an OpenEXR file (a " + in.format_name() + " file)");
  Image image(header.width, header.height, header.channels);
  image.channel_names = header.channel_names;
  in.read(header.channels, SampleType::kFloat, image.data.data());
  metadata = {};
  for (const auto& [name, value] : header.text_attributes) {
    if (name == "ImageDescription")
      metadata.description = value;
    else
      metadata.attributes.emplace_back(name, value);
  }
  return image;
}

Image read_image(const std::string& path) {
  CheckedImageInput in = CheckedImageInput::open_file(path);
  const ImageHeader& header = in.header();
  Image image(header.width, header.height, header.channels);
  image.channel_names = header.channel_names;
  in.read(header.channels, SampleType::kFloat, image.data.data());
  return image;
}

}  // namespace obscura
