// The native image codecs (plugins/image_codecs): each format's encoder and decoder round trip
// (written → read back equal: exactly for the lossless ones), OpenImageIO — an independent
// reader — reads what they write with the same values and attributes, and a corrupt or
// truncated file of each format is an obscura::Error that names it.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include "obscura/io/image_codecs_loader.h"
#include "obscura/io/image_reader.h"
#include "obscura/math/error.h"
#include "run_command.h"
#include "test_files.h"

namespace obscura {
namespace {

using test::error_of;
using test::file_bytes;
using test::put_file;

size_t value_size(SampleType type) {
  return type == SampleType::kUint8 ? 1 : type == SampleType::kFloat ? 4 : 2;
}

// Values that use the whole range of `type` (and, for floats, more than [0, 1]).
std::vector<unsigned char> pattern(int width, int height, int channels, SampleType type) {
  const size_t count = size_t(width) * size_t(height) * size_t(channels);
  std::vector<unsigned char> bytes(count * value_size(type));
  for (size_t i = 0; i < count; ++i) {
    if (type == SampleType::kUint8) {
      bytes[i] = uint8_t((i * 37 + 11) % 256);
    } else if (type == SampleType::kUint16) {
      uint16_t v = uint16_t((i * 4099 + 7) % 65536);
      std::memcpy(&bytes[2 * i], &v, 2);
    } else {
      float v = 0.125f * float(i % 97) - 2.f;
      std::memcpy(&bytes[4 * i], &v, 4);
    }
  }
  return bytes;
}

EncodeRequest request_for(const std::string& name, int width, int height, int channels,
                          SampleType type, const std::vector<unsigned char>& data) {
  EncodeRequest r;
  r.path = name;
  r.width = width;
  r.height = height;
  r.channels = channels;
  r.stored = type;
  r.data_type = type;
  r.data = data.data();
  return r;
}

struct Decoded {
  ImageHeader header;
  std::vector<unsigned char> values;
};

Decoded decode(const std::vector<unsigned char>& file, const std::string& name, SampleType type) {
  CheckedImageInput in = CheckedImageInput::open_memory(file, name, "");
  Decoded d{in.header(), {}};
  d.values.resize(size_t(d.header.width) * size_t(d.header.height) * size_t(d.header.channels) *
                  value_size(type));
  in.read(d.header.channels, type, d.values.data());
  return d;
}

class NativeImageCodecs : public test::TempDirTest {};

TEST_F(NativeImageCodecs, PngRoundTripsEveryChannelCountIn8And16Bits) {
  for (SampleType type : {SampleType::kUint8, SampleType::kUint16})
    for (int channels = 1; channels <= 4; ++channels) {
      SCOPED_TRACE(std::to_string(channels) + " channels, " + std::to_string(value_size(type)));
      auto data = pattern(7, 5, channels, type);
      auto file = image_codecs().encode(request_for("t.png", 7, 5, channels, type, data));
      Decoded d = decode(file, "t.png", type);
      EXPECT_EQ(d.header.format_name, "png");
      EXPECT_EQ(d.header.format, type);
      EXPECT_EQ(d.header.channels, channels);
      EXPECT_EQ(d.values, data);
      // OpenImageIO reads the same values.
      put_file(path("t.png"), file);
      auto in = OIIO::ImageInput::open(path("t.png"));
      ASSERT_TRUE(in);
      std::vector<unsigned char> oiio(data.size());
      ASSERT_TRUE(in->read_image(
          0, 0, 0, channels,
          type == SampleType::kUint8 ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::UINT16,
          oiio.data()));
      if (channels % 2 == 1) {  // with alpha, OpenImageIO premultiplies
        EXPECT_EQ(oiio, data);
      }
    }
}

TEST_F(NativeImageCodecs, PngTextAttributesAndSrgbTagRoundTrip) {
  auto data = pattern(3, 2, 3, SampleType::kUint8);
  EncodeRequest r = request_for("t.png", 3, 2, 3, SampleType::kUint8, data);
  r.attributes = {{"oiio:ColorSpace", std::string("sRGB")},
                  {"ImageDescription", std::string("a partial render")},
                  {"obscura:partial", std::string("time limit")},
                  {"obscura:bits", 8}};
  auto file = image_codecs().encode(r);
  Decoded d = decode(file, "t.png", SampleType::kUint8);
  EXPECT_TRUE(d.header.has_attribute("ImageDescription"));
  put_file(path("t.png"), file);
  auto in = OIIO::ImageInput::open(path("t.png"));
  ASSERT_TRUE(in);
  EXPECT_EQ(in->spec().get_string_attribute("ImageDescription"), "a partial render");
  EXPECT_EQ(in->spec().get_string_attribute("obscura:partial"), "time limit");
  EXPECT_EQ(in->spec().get_string_attribute("oiio:ColorSpace"), "sRGB");
}

TEST_F(NativeImageCodecs, TiffRoundTripsIntegersAndFloats) {
  for (SampleType type : {SampleType::kUint8, SampleType::kUint16, SampleType::kFloat})
    for (int channels = 1; channels <= 4; ++channels) {
      SCOPED_TRACE(std::to_string(channels) + " channels, " + std::to_string(value_size(type)));
      // 70 rows: more than one strip of 32.
      auto data = pattern(9, 70, channels, type);
      EncodeRequest r = request_for("t.tif", 9, 70, channels, type, data);
      r.attributes = {{"ImageDescription", std::string("described")}};
      auto file = image_codecs().encode(r);
      Decoded d = decode(file, "t.tif", type);
      EXPECT_EQ(d.header.format_name, "tiff");
      EXPECT_EQ(d.header.channels, channels);
      EXPECT_EQ(d.values, data);
      put_file(path("t.tif"), file);
      auto in = OIIO::ImageInput::open(path("t.tif"));
      ASSERT_TRUE(in) << OIIO::geterror();
      EXPECT_EQ(in->spec().get_string_attribute("ImageDescription"), "described");
      std::vector<unsigned char> oiio(data.size());
      ASSERT_TRUE(in->read_image(0, 0, 0, channels, OIIO::TypeDesc::UNKNOWN, oiio.data()));
      if (channels % 2 == 1) {  // with alpha, OpenImageIO premultiplies
        EXPECT_EQ(oiio, data);
      }
    }
}

TEST_F(NativeImageCodecs, ExrRoundTripsFloatAndHalfWithNamesAndAttributes) {
  auto data = pattern(6, 4, 3, SampleType::kFloat);
  EncodeRequest r = request_for("t.exr", 6, 4, 3, SampleType::kFloat, data);
  r.channel_names = {"X", "Y", "Z"};
  r.attributes = {{"ImageDescription", std::string("normals")},
                  {"obscura:partial", std::string("interrupted")},
                  {"obscura:bits", 12},
                  {"compression", std::string("zip")}};
  auto file = image_codecs().encode(r);
  Decoded d = decode(file, "t.exr", SampleType::kFloat);
  EXPECT_EQ(d.header.format_name, "openexr");
  EXPECT_EQ(d.header.channel_names, (std::vector<std::string>{"X", "Y", "Z"}));
  EXPECT_EQ(d.values, data);
  put_file(path("t.exr"), file);
  {
    auto in = OIIO::ImageInput::open(path("t.exr"));
    ASSERT_TRUE(in);
    EXPECT_EQ(in->spec().get_string_attribute("ImageDescription"), "normals");
    EXPECT_EQ(in->spec().get_string_attribute("obscura:partial"), "interrupted");
    EXPECT_EQ(in->spec().get_int_attribute("obscura:bits"), 12);
    EXPECT_EQ(in->spec().get_string_attribute("compression"), "zip");
  }
  // Half: the values above are all exact in half.
  r.stored = SampleType::kHalf;
  r.channel_names = {"R", "G", "B"};
  Decoded h = decode(image_codecs().encode(r), "h.exr", SampleType::kFloat);
  EXPECT_EQ(h.header.format, SampleType::kHalf);
  EXPECT_EQ(h.values, data);
}

// A megapixel and more is (de)compressed on OpenEXR's thread pool: the same values.
TEST_F(NativeImageCodecs, ALargeExrRoundTripsOnSeveralThreads) {
  auto data = pattern(1024, 1030, 3, SampleType::kFloat);
  auto file =
      image_codecs().encode(request_for("big.exr", 1024, 1030, 3, SampleType::kFloat, data));
  Decoded d = decode(file, "big.exr", SampleType::kFloat);
  EXPECT_EQ(d.header.height, 1030);
  EXPECT_TRUE(d.values == data);
}

TEST_F(NativeImageCodecs, ExrChannelsComeBackInTheOrderOpenImageIoGave) {
  // The file sorts them (B, G, R, W, albedo.B…); RGB first, then the rest, then each layer.
  std::vector<std::string> names = {"R", "G", "B", "W", "albedo.R", "albedo.G", "albedo.B", "id"};
  auto data = pattern(2, 2, int(names.size()), SampleType::kFloat);
  EncodeRequest r = request_for("t.exr", 2, 2, int(names.size()), SampleType::kFloat, data);
  r.channel_names = names;
  auto file = image_codecs().encode(r);
  Decoded d = decode(file, "t.exr", SampleType::kFloat);
  put_file(path("t.exr"), file);
  auto in = OIIO::ImageInput::open(path("t.exr"));
  ASSERT_TRUE(in);
  EXPECT_EQ(d.header.channel_names, in->spec().channelnames);
  EXPECT_EQ(d.header.channel_names, (std::vector<std::string>{"R", "G", "B", "W", "id", "albedo.R",
                                                              "albedo.G", "albedo.B"}));
}

TEST_F(NativeImageCodecs, JpegKeepsAFlatImageAndItsDescription) {
  std::vector<unsigned char> grey(16 * 8 * 3, 128);
  EncodeRequest r = request_for("t.jpg", 16, 8, 3, SampleType::kUint8, grey);
  r.attributes = {{"Compression", std::string("jpeg:95")},
                  {"ImageDescription", std::string("seen through JPEG")}};
  auto file = image_codecs().encode(r);
  Decoded d = decode(file, "t.jpg", SampleType::kUint8);
  EXPECT_EQ(d.header.format_name, "jpeg");
  EXPECT_EQ(d.header.channels, 3);
  for (unsigned char v : d.values) EXPECT_NEAR(int(v), 128, 1);
  put_file(path("t.jpg"), file);
  auto in = OIIO::ImageInput::open(path("t.jpg"));
  ASSERT_TRUE(in);
  EXPECT_EQ(in->spec().get_string_attribute("ImageDescription"), "seen through JPEG");
  // Grey stays one channel.
  std::vector<unsigned char> one(16 * 8, 200);
  Decoded g = decode(image_codecs().encode(request_for("g.jpg", 16, 8, 1, SampleType::kUint8, one)),
                     "g.jpg", SampleType::kUint8);
  EXPECT_EQ(g.header.channels, 1);
  for (unsigned char v : g.values) EXPECT_NEAR(int(v), 200, 1);
}

TEST_F(NativeImageCodecs, SixteenBitsReadAsFloatAreTheirFractionOf65535) {
  std::vector<uint16_t> values = {0, 1, 32768, 65535};
  std::vector<unsigned char> data(8);
  std::memcpy(data.data(), values.data(), 8);
  auto file = image_codecs().encode(request_for("t.png", 4, 1, 1, SampleType::kUint16, data));
  Decoded d = decode(file, "t.png", SampleType::kFloat);
  std::vector<float> f(4);
  std::memcpy(f.data(), d.values.data(), 16);
  EXPECT_FLOAT_EQ(f[1], 1.f / 65535.f);
  EXPECT_FLOAT_EQ(f[2], 32768.f / 65535.f);
  EXPECT_FLOAT_EQ(f[3], 1.f);
}

// PFM (netpbm's float map): rows bottom to top, the scale's sign the byte order.
TEST_F(NativeImageCodecs, PfmIsReadBottomUpInEitherByteOrder) {
  auto pfm = [](const std::string& header, std::vector<float> values, bool big_endian) {
    std::vector<unsigned char> file(header.begin(), header.end());
    for (float v : values) {
      unsigned char b[4];
      std::memcpy(b, &v, 4);
      if (big_endian) std::swap(b[0], b[3]), std::swap(b[1], b[2]);
      file.insert(file.end(), b, b + 4);
    }
    return file;
  };
  auto floats = [](const Decoded& d) {
    std::vector<float> f(d.values.size() / 4);
    std::memcpy(f.data(), d.values.data(), d.values.size());
    return f;
  };
  // Grey, 2 × 2: the file's first row (1, 2) is the image's bottom row.
  Decoded grey = decode(pfm("Pf\n2 2\n-1.0\n", {1, 2, 3, 4}, false), "g.pfm", SampleType::kFloat);
  EXPECT_EQ(grey.header.channels, 1);
  EXPECT_EQ(floats(grey), (std::vector<float>{3, 4, 1, 2}));
  Decoded rgb = decode(pfm("PF 1 1 1.0 ", {0.5f, -2.f, 1e20f}, true), "c.pfm", SampleType::kFloat);
  EXPECT_EQ(rgb.header.channel_names, (std::vector<std::string>{"R", "G", "B"}));
  EXPECT_EQ(floats(rgb), (std::vector<float>{0.5f, -2.f, 1e20f}));
  std::string short_file = error_of([&] {
    decode(pfm("PF\n2 2\n-1.0\n", {1, 2, 3}, false), "cut.pfm", SampleType::kFloat);
  });
  EXPECT_NE(short_file.find("cut.pfm"), std::string::npos) << short_file;
  EXPECT_NE(short_file.find("truncated"), std::string::npos) << short_file;
  std::string no_scale =
      error_of([&] { decode(pfm("PF\n2 2\nabc\n", {}, false), "s.pfm", SampleType::kFloat); });
  EXPECT_NE(no_scale.find("scale"), std::string::npos) << no_scale;
}

// Every format, cut short or with its middle overwritten: an obscura::Error naming the image,
// never a crash, a hang or an exit.
TEST_F(NativeImageCodecs, CorruptAndTruncatedFilesOfEachFormatAreErrorsNamingThem) {
  struct Case {
    const char* name;
    SampleType type;
  };
  for (Case c : {Case{"c.png", SampleType::kUint8}, Case{"c.jpg", SampleType::kUint8},
                 Case{"c.tif", SampleType::kUint16}, Case{"c.exr", SampleType::kFloat},
                 Case{"c.hdr", SampleType::kFloat}}) {
    SCOPED_TRACE(c.name);
    auto data = pattern(40, 40, 3, c.type);
    auto file = image_codecs().encode(request_for(c.name, 40, 40, 3, c.type, data));
    std::vector<unsigned char> cut(file.begin(), file.begin() + long(file.size() / 2));
    std::string message = error_of([&] { decode(cut, std::string("cut-") + c.name, c.type); });
    EXPECT_NE(message.find(std::string("cut-") + c.name), std::string::npos) << message;
    EXPECT_NE(message.find("cannot read image as"), std::string::npos) << message;
    // The header kept, everything after it garbage.
    std::vector<unsigned char> garbled = file;
    for (size_t i = garbled.size() / 8; i < garbled.size(); ++i) garbled[i] = uint8_t(i * 131);
    message = error_of([&] { decode(garbled, std::string("bad-") + c.name, c.type); });
    EXPECT_NE(message.find(std::string("bad-") + c.name), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace obscura
