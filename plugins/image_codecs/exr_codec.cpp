#include "exr_codec.h"

#include <Imath/ImathBox.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfChromaticitiesAttribute.h>
#include <OpenEXR/ImfFloatAttribute.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfThreading.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <exception>
#include <map>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>

#include "encode_attributes.h"
#include "exr_channel_order.h"
#include "obscura/math/error.h"
#include "sample_conversion.h"

namespace obscura::codecs {

namespace {

// An encoded file in memory as OpenEXR's input stream; reading past its end throws.
class MemoryInput final : public Imf::IStream {
 public:
  explicit MemoryInput(std::span<const uint8_t> bytes) : IStream("memory"), bytes_(bytes) {}
  bool isMemoryMapped() const override { return true; }
  bool read(char c[], int n) override {
    std::memcpy(c, take(n), size_t(n));
    return position_ < bytes_.size();
  }
  char* readMemoryMapped(int n) override { return const_cast<char*>(take(n)); }
  uint64_t tellg() override { return position_; }
  void seekg(uint64_t position) override { position_ = position; }

 private:
  const char* take(int n) {
    if (n < 0 || position_ > bytes_.size() || size_t(n) > bytes_.size() - position_)
      throw std::runtime_error("the file is truncated");
    const char* at = reinterpret_cast<const char*>(bytes_.data() + position_);
    position_ += size_t(n);
    return at;
  }
  std::span<const uint8_t> bytes_;
  uint64_t position_ = 0;
};

class MemoryOutput final : public Imf::OStream {
 public:
  explicit MemoryOutput(std::vector<unsigned char>& bytes) : OStream("memory"), bytes_(bytes) {}
  void write(const char c[], int n) override {
    if (position_ + size_t(n) > bytes_.size()) bytes_.resize(position_ + size_t(n));
    std::memcpy(bytes_.data() + position_, c, size_t(n));
    position_ += size_t(n);
  }
  uint64_t tellp() override { return position_; }
  void seekp(uint64_t position) override { position_ = position; }

 private:
  std::vector<unsigned char>& bytes_;
  uint64_t position_ = 0;
};

SampleType sample_type(Imf::PixelType type) {
  switch (type) {
    case Imf::HALF:
      return SampleType::kHalf;
    case Imf::FLOAT:
      return SampleType::kFloat;
    default:
      return SampleType::kOther;
  }
}

// OpenImageIO's names for OpenEXR's standard text attributes.
std::string attribute_name(const std::string& exr_name) {
  if (exr_name == "comments") return "ImageDescription";
  if (exr_name == "owner") return "Copyright";
  if (exr_name == "capDate") return "DateTime";
  return exr_name;
}

// Threads for (de)compressing an image of `pixels`: all cores from a megapixel on, as OpenImageIO
// did; none below (starting OpenEXR's pool costs more than it saves on a small image).
int exr_threads_for(size_t pixels) {
  if (pixels < (size_t(1) << 20)) return 0;
  static std::once_flag pool;
  std::call_once(pool, [] {
    if (Imf::globalThreadCount() == 0)
      Imf::setGlobalThreadCount(int(std::max(1u, std::thread::hardware_concurrency())));
  });
  return Imf::globalThreadCount();
}

// Version field flags (OpenEXR file layout): deep data, several parts.
constexpr uint32_t kNonImageFlag = 0x800;

class ExrDecoder final : public ImageDecoder {
 public:
  explicit ExrDecoder(EncodedBytes encoded)
      : encoded_(std::move(encoded)), stream_(encoded_.bytes) {
    header_.format_name = "openexr";
    uint32_t version = 0;
    if (encoded_.bytes.size() >= 8) std::memcpy(&version, encoded_.bytes.data() + 4, 4);
    if (version & kNonImageFlag) {  // deep: only what the caller needs to refuse it
      header_.deep = true;
      return;
    }
    guarded([&] {
      file_ = std::make_unique<Imf::InputFile>(stream_, 0);
      const Imath::Box2i window = file_->header().dataWindow();
      // In 64 bits: a hostile window overflows int; one out of range is left 0 for the
      // caller's size check to refuse.
      auto extent = [](int lo, int hi) {
        int64_t n = int64_t(hi) - int64_t(lo) + 1;
        return n > 0 && n <= INT32_MAX ? int(n) : 0;
      };
      header_.width = extent(window.min.x, window.max.x);
      header_.height = extent(window.min.y, window.max.y);
      // A large image is opened again to decompress on all cores (the thread count is fixed
      // when the file is opened; the size is known only from its header).
      if (int threads = exr_threads_for(size_t(header_.width) * size_t(header_.height))) {
        file_.reset();
        stream_.seekg(0);
        file_ = std::make_unique<Imf::InputFile>(stream_, threads);
      }
      const Imf::Header& h = file_->header();
      std::vector<std::string> names;
      for (auto c = h.channels().begin(); c != h.channels().end(); ++c) {
        names.push_back(c.name());
        if (c.channel().xSampling != 1 || c.channel().ySampling != 1) subsampled_ = true;
      }
      header_.channel_names = exr_channel_order(names);
      header_.channels = int(names.size());
      if (!names.empty())
        header_.format = sample_type(h.channels().find(header_.channel_names[0]).channel().type);
      for (auto a = h.begin(); a != h.end(); ++a)
        if (const auto* text = dynamic_cast<const Imf::StringAttribute*>(&a.attribute()))
          header_.text_attributes.emplace_back(attribute_name(a.name()), text->value());
    });
  }

  const ImageHeader& header() const override { return header_; }
  bool supported() const { return !subsampled_; }

  void read(int channels, SampleType type, void* pixels) override {
    if (!file_ || channels < 1 || channels > header_.channels || type == SampleType::kOther)
      throw Error(encoded_.source,
                  "cannot read " + std::to_string(channels) + " channels of this OpenEXR image");
    // OpenEXR converts half, float and uint itself; 8 and 16 bits go through float.
    const bool direct = type == SampleType::kHalf || type == SampleType::kFloat;
    const SampleType read_type = direct ? type : SampleType::kFloat;
    const size_t pixel_count = size_t(header_.width) * size_t(header_.height);
    std::vector<unsigned char> staging;
    void* target = pixels;
    if (!direct) {
      staging.resize(pixel_count * size_t(channels) * 4);
      target = staging.data();
    }
    guarded([&] {
      const Imath::Box2i window = file_->header().dataWindow();
      const size_t value = sample_size(read_type), pixel = value * size_t(channels);
      Imf::FrameBuffer frame;
      for (int c = 0; c < channels; ++c)
        frame.insert(header_.channel_names[size_t(c)],
                     Imf::Slice::Make(read_type == SampleType::kHalf ? Imf::HALF : Imf::FLOAT,
                                      static_cast<unsigned char*>(target) + size_t(c) * value,
                                      window, pixel, pixel * size_t(header_.width)));
      file_->setFrameBuffer(frame);
      file_->readPixels(window.min.y, window.max.y);
    });
    if (!direct) convert_samples(SampleType::kFloat, target, type, pixels, pixel_count * channels);
  }

 private:
  // OpenEXR reports errors (of a corrupt or truncated file too) as exceptions of its own.
  template <typename F>
  void guarded(F&& f) {
    try {
      f();
    } catch (const Error&) {
      throw;
    } catch (const std::exception& e) {
      throw Error(encoded_.source, std::string("cannot read image as openexr: ") + e.what());
    }
  }

  EncodedBytes encoded_;
  MemoryInput stream_;
  std::unique_ptr<Imf::InputFile> file_;
  ImageHeader header_;
  bool subsampled_ = false;
};

Imf::Compression compression_of(const EncodeRequest& request) {
  static const std::map<std::string, Imf::Compression> kNames = {
      {"none", Imf::NO_COMPRESSION},   {"rle", Imf::RLE_COMPRESSION},
      {"zips", Imf::ZIPS_COMPRESSION}, {"zip", Imf::ZIP_COMPRESSION},
      {"piz", Imf::PIZ_COMPRESSION},   {"pxr24", Imf::PXR24_COMPRESSION},
      {"b44", Imf::B44_COMPRESSION},   {"b44a", Imf::B44A_COMPRESSION},
      {"dwaa", Imf::DWAA_COMPRESSION}, {"dwab", Imf::DWAB_COMPRESSION}};
  const std::string* name = text_attribute(request, "compression");
  if (!name) return Imf::ZIP_COMPRESSION;  // OpenImageIO's default for OpenEXR
  auto found = kNames.find(*name);
  if (found == kNames.end())
    throw Error(request.path, "unknown OpenEXR compression '" + *name + "'");
  return found->second;
}

void add_attribute(Imf::Header& header, const HeaderAttribute& attribute) {
  const std::string& name = attribute.name;
  if (name == "compression" || name.rfind("oiio:", 0) == 0) return;
  if (const auto* text = std::get_if<std::string>(&attribute.value)) {
    header.insert(name == "ImageDescription" ? "comments" : name, Imf::StringAttribute(*text));
  } else if (const auto* number = std::get_if<int>(&attribute.value)) {
    header.insert(name, Imf::IntAttribute(*number));
  } else if (const auto* floats = std::get_if<std::vector<float>>(&attribute.value)) {
    const std::vector<float>& f = *floats;
    if (name == "chromaticities" && f.size() == 8)
      header.insert(name, Imf::ChromaticitiesAttribute(Imf::Chromaticities(
                              {f[0], f[1]}, {f[2], f[3]}, {f[4], f[5]}, {f[6], f[7]})));
    else if (f.size() == 1)
      header.insert(name, Imf::FloatAttribute(f[0]));
  }
}

std::vector<std::string> exr_default_names(int channels) {
  if (channels == 1) return {"Y"};
  std::vector<std::string> names;
  static const char* kRgba[] = {"R", "G", "B", "A"};
  for (int c = 0; c < channels; ++c)
    names.push_back(c < 4 ? kRgba[c] : "channel" + std::to_string(c));
  return names;
}

}  // namespace

std::unique_ptr<ImageDecoder> open_exr(EncodedBytes encoded) {
  auto decoder = std::make_unique<ExrDecoder>(std::move(encoded));
  if (!decoder->supported()) return nullptr;
  return decoder;
}

std::vector<unsigned char> encode_exr(const EncodeRequest& request) {
  check_request(request, 1 << 16);
  std::vector<std::string> names =
      request.channel_names.empty() ? exr_default_names(request.channels) : request.channel_names;
  if (int(names.size()) != request.channels)
    throw Error(request.path, "cannot encode OpenEXR: " + std::to_string(names.size()) +
                                  " channel names for " + std::to_string(request.channels) +
                                  " channels");
  const Imf::PixelType stored = request.stored == SampleType::kHalf ? Imf::HALF : Imf::FLOAT;
  // OpenEXR writes each channel from a buffer of its own type: half is converted here (Imath's
  // rounding to nearest, as OpenImageIO did).
  const SampleType stored_type = stored == Imf::HALF ? SampleType::kHalf : SampleType::kFloat;
  std::vector<unsigned char> converted;
  const void* data = request.data;
  if (request.data_type != stored_type) {
    converted = request_pixels(request, stored_type);
    data = converted.data();
  }
  const size_t value = sample_size(stored_type);
  std::vector<unsigned char> encoded;
  try {
    Imf::Header header(request.width, request.height);
    header.compression() = compression_of(request);
    for (const std::string& name : names) header.channels().insert(name, Imf::Channel(stored));
    for (const HeaderAttribute& attribute : request.attributes) add_attribute(header, attribute);
    const size_t pixel = value * size_t(request.channels);
    Imf::FrameBuffer frame;
    for (size_t c = 0; c < names.size(); ++c)
      frame.insert(names[c],
                   Imf::Slice(stored, const_cast<char*>(static_cast<const char*>(data)) + value * c,
                              pixel, pixel * size_t(request.width)));
    MemoryOutput out(encoded);
    Imf::OutputFile file(out, header,
                         exr_threads_for(size_t(request.width) * size_t(request.height)));
    file.setFrameBuffer(frame);
    file.writePixels(request.height);
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    throw Error(request.path, std::string("cannot encode OpenEXR: ") + e.what());
  }
  return encoded;
}

}  // namespace obscura::codecs
