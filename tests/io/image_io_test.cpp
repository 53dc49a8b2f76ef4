#include "obscura/io/image_io.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include <OpenImageIO/imageio.h>

#include "obscura/color/srgb.h"
#include "obscura/io/y4m_writer.h"
#include "obscura/math/error.h"
#include "run_command.h"

namespace obscura {
namespace {

namespace fs = std::filesystem;

Image gradient(int w, int h) {
  Image image(w, h, 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      image.set_rgb(x, y, Rgb(float(x) / w, float(y) / h, 0.25f * (x + y) - 1.5f));
  return image;
}

TEST(Srgb, EncodesKnownValues) {
  // IEC 61966-2-1: 0.5 linear is 0.735357 encoded; the break points 0.0031308 ↔ 0.04045.
  EXPECT_NEAR(srgb_encode(0.5f), 0.735357f, 1e-6f);
  EXPECT_NEAR(srgb_encode(0.0031308f), 0.04045f, 1e-6f);
  EXPECT_NEAR(srgb_encode(0.18f), 0.461356f, 1e-6f);
  EXPECT_FLOAT_EQ(srgb_encode(1.f), 1.f);
  EXPECT_FLOAT_EQ(srgb_encode(0.f), 0.f);
  for (float v = 0; v <= 1; v += 1.f / 64) EXPECT_NEAR(srgb_decode(srgb_encode(v)), v, 1e-6f);
}

class ImageIo : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = test::make_temp_dir("obscura-io"); }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (fs::path(dir_) / name).string(); }
  // Only the named file is left in the directory: no temporary files behind.
  void expect_only(const std::string& name) const {
    int count = 0;
    for (const auto& entry : fs::directory_iterator(dir_)) {
      ++count;
      EXPECT_EQ(entry.path().filename().string(), name);
    }
    EXPECT_EQ(count, 1);
  }
  std::string dir_;
};

TEST_F(ImageIo, PngIsSrgbEncoded8Bit) {
  Image image(3, 1, 3);
  image.set_rgb(0, 0, Rgb(0.5f, 0.18f, 0.f));
  image.set_rgb(1, 0, Rgb(1.f, 2.f, -1.f));  // clamped to [0, 1]
  image.set_rgb(2, 0, Rgb(0.0031308f, 0.2158605f, 1.f));
  write_image(path("a.png"), image);
  expect_only("a.png");
  Image back = read_image(path("a.png"));
  ASSERT_EQ(back.width, 3);
  ASSERT_EQ(back.height, 1);
  // 0.735357 · 255 = 187.5 → 188; 0.461356 · 255 = 117.6 → 118; 0.04045 · 255 = 10.3 → 10;
  // linear 0.2158605 is the decoded value of 128/255.
  EXPECT_EQ(std::lround(back.at(0, 0, 0) * 255), 188);
  EXPECT_EQ(std::lround(back.at(0, 0, 1) * 255), 118);
  EXPECT_EQ(std::lround(back.at(0, 0, 2) * 255), 0);
  EXPECT_EQ(std::lround(back.at(1, 0, 0) * 255), 255);
  EXPECT_EQ(std::lround(back.at(1, 0, 1) * 255), 255);
  EXPECT_EQ(std::lround(back.at(1, 0, 2) * 255), 0);
  EXPECT_EQ(std::lround(back.at(2, 0, 0) * 255), 10);
  EXPECT_EQ(std::lround(back.at(2, 0, 1) * 255), 128);
}

TEST_F(ImageIo, ExrRoundTripsFloatsExactly) {
  Image image = gradient(17, 9);
  write_image(path("a.exr"), image);
  expect_only("a.exr");
  Image back = read_image(path("a.exr"));
  ASSERT_EQ(back.width, 17);
  ASSERT_EQ(back.height, 9);
  ASSERT_EQ(back.channels, 3);
  EXPECT_EQ(back.data, image.data);
}

TEST_F(ImageIo, PfmRoundTripsAndFollowsTheFormat) {
  Image image = gradient(5, 3);
  write_image(path("a.pfm"), image);
  Image back = read_image(path("a.pfm"));
  EXPECT_EQ(back.data, image.data);

  // Read the file by hand: "PF\n5 3\n<scale>\n" then little-endian (negative scale) float rows
  // from the bottom of the image to the top.
  std::ifstream in(path("a.pfm"), std::ios::binary);
  std::string magic;
  int w, h;
  double scale;
  in >> magic >> w >> h >> scale;
  in.get();
  ASSERT_EQ(magic, "PF");
  ASSERT_EQ(w, 5);
  ASSERT_EQ(h, 3);
  ASSERT_LT(scale, 0);  // little-endian
  std::vector<float> raw(5 * 3 * 3);
  in.read(reinterpret_cast<char*>(raw.data()), raw.size() * sizeof(float));
  ASSERT_TRUE(in.good());
  for (int row = 0; row < 3; ++row)
    for (int x = 0; x < 5; ++x)
      for (int c = 0; c < 3; ++c) EXPECT_EQ(raw[(row * 5 + x) * 3 + c], image.at(x, 2 - row, c));
}

TEST_F(ImageIo, RejectsBadPathsBeforeWriting) {
  Image image = gradient(2, 2);
  EXPECT_THROW(write_image(path("a.bmp"), image), Error);
  EXPECT_THROW(write_image(path("missing/a.png"), image), Error);
  fs::create_directory(path("sub"));
  EXPECT_THROW(write_image(path("sub"), image), Error);
  try {
    check_output_path(path("missing/a.png"));
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("does not exist"), std::string::npos) << e.what();
  }
  expect_only("sub");
}

TEST_F(ImageIo, FailedWriteLeavesNoFile) {
  // /proc refuses new files even to root: the write fails after the checks pass.
  EXPECT_THROW(write_image("/proc/obscura-io-test.png", gradient(2, 2)), Error);
  EXPECT_FALSE(fs::exists("/proc/obscura-io-test.png"));
}

TEST_F(ImageIo, NonFiniteValuesBecomeBlackInPng) {
  Image image(2, 1, 3);
  image.set_rgb(0, 0, Rgb(NAN, INFINITY, -INFINITY));
  image.set_rgb(1, 0, Rgb(1, 1, 1));
  write_image(path("nan.png"), image);
  Image back = read_image(path("nan.png"));
  EXPECT_EQ(back.at(0, 0, 0), 0.f);
  EXPECT_EQ(back.at(0, 0, 1), 0.f);
  EXPECT_EQ(back.at(0, 0, 2), 0.f);
}

// Formats and options beyond the defaults: bit depths, displays, half floats, HDR, Y4M.
class ImageFormats : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = test::make_temp_dir("obscura-formats"); }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (fs::path(dir_) / name).string(); }

  // A 4×2 test image: distinct values, including above 1 and a top-left marker.
  static Image sample() {
    Image im(4, 2, 3);
    for (size_t i = 0; i < im.data.size(); ++i) im.data[i] = 0.05f * float(i);
    im.data[0] = 0.5f;
    return im;
  }

  std::string dir_;
};

TEST_F(ImageFormats, Png8BitIsSrgbEncodedAndTagged) {
  Image im = sample();
  write_image(path("a.png"), im);
  Image back = read_image(path("a.png"));
  ASSERT_EQ(back.width, 4);
  ASSERT_EQ(back.channels, 3);
  // Linear 0.5 → sRGB 0.735357 → code 188 (IEC 61966-2-1).
  EXPECT_FLOAT_EQ(back.data[0], 188.f / 255);
  auto in = OIIO::ImageInput::open(path("a.png"));
  ASSERT_TRUE(in);
  EXPECT_EQ(in->spec().format, OIIO::TypeDesc::UINT8);
  EXPECT_EQ(in->spec().get_string_attribute("oiio:ColorSpace"), "sRGB");
}

TEST_F(ImageFormats, Png16BitAndFewBits) {
  Image im = sample();
  ImageWriteOptions sixteen;
  sixteen.display.bits = 16;
  write_image(path("a16.png"), im, sixteen);
  auto in = OIIO::ImageInput::open(path("a16.png"));
  ASSERT_TRUE(in);
  EXPECT_EQ(in->spec().format, OIIO::TypeDesc::UINT16);
  EXPECT_NEAR(read_image(path("a16.png")).data[0], 0.735356983, 1.0 / 65535);

  // 5 bits: 0.735357·31 = 22.8 → 23, spread to 8 bits: round(23·255/31) = 189.
  ImageWriteOptions five;
  five.display.bits = 5;
  write_image(path("a5.png"), im, five);
  EXPECT_FLOAT_EQ(read_image(path("a5.png")).data[0], 189.f / 255);
}

TEST_F(ImageFormats, DisplayP3PngIsEncodedForP3) {
  Image red(1, 1, 3);
  red.data = {1, 0, 0};
  ImageWriteOptions p3;
  p3.display.display = DisplaySpace::kDisplayP3;
  write_image(path("p3.png"), red, p3);
  Image back = read_image(path("p3.png"));
  // sRGB red in Display P3 is (0.9175, 0.2003, 0.1386) (encoded; shared vectors / OCIO probe).
  EXPECT_FLOAT_EQ(back.data[0], 234.f / 255);
  EXPECT_FLOAT_EQ(back.data[1], 51.f / 255);
  EXPECT_FLOAT_EQ(back.data[2], 35.f / 255);
}

TEST_F(ImageFormats, ExrFloatAndHalfWithChromaticities) {
  Image im = sample();
  write_image(path("f.exr"), im);
  EXPECT_EQ(read_image(path("f.exr")).data, im.data);
  ImageWriteOptions half;
  half.exr_half = true;
  write_image(path("h.exr"), im, half);
  Image back = read_image(path("h.exr"));
  for (size_t i = 0; i < im.data.size(); ++i)
    EXPECT_NEAR(back.data[i], im.data[i], 1e-3 * im.data[i] + 1e-6);
  auto in = OIIO::ImageInput::open(path("h.exr"));
  ASSERT_TRUE(in);
  EXPECT_EQ(in->spec().format, OIIO::TypeDesc::HALF);
  const OIIO::ParamValue* c = in->spec().find_attribute("chromaticities");
  ASSERT_NE(c, nullptr);
  const float* xy = static_cast<const float*>(c->data());
  EXPECT_FLOAT_EQ(xy[0], 0.64f);
  EXPECT_FLOAT_EQ(xy[6], 0.3127f);
}

TEST_F(ImageFormats, RadianceHdrAndPfmRoundTrip) {
  Image im = sample();
  write_image(path("a.hdr"), im);
  Image hdr = read_image(path("a.hdr"));
  // RGBE: an 8-bit mantissa per channel with the pixel's shared exponent, so the error is
  // relative to the pixel's largest channel.
  for (size_t p = 0; p < im.data.size() / 3; ++p) {
    float largest = std::max({im.data[3 * p], im.data[3 * p + 1], im.data[3 * p + 2]});
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(hdr.data[3 * p + k], im.data[3 * p + k], largest / 128);
  }
  write_image(path("a.pfm"), im);
  Image pfm = read_image(path("a.pfm"));
  EXPECT_EQ(pfm.data, im.data);  // exact, and the same way up (row 0 at the top)
}

TEST_F(ImageFormats, NanAndInfBecomeDefinedValuesAndAreCounted) {
  Image im(2, 2, 3);
  im.data = {std::nanf(""),
             0.5f,
             0.5f,
             std::numeric_limits<float>::infinity(),
             0,
             0,
             -std::numeric_limits<float>::infinity(),
             0,
             0,
             0.5f,
             0.5f,
             0.5f};
  WriteReport png = write_image(path("bad.png"), im);
  EXPECT_EQ(png.stats.nan_pixels, 1u);
  EXPECT_EQ(png.stats.inf_pixels, 2u);
  Image back = read_image(path("bad.png"));
  EXPECT_EQ(back.data[0], 0.f);
  EXPECT_EQ(back.data[3], 0.f);
  EXPECT_EQ(back.data[6], 0.f);
  WriteReport exr = write_image(path("bad.exr"), im);
  EXPECT_EQ(exr.stats.nan_pixels, 1u);
  Image linear = read_image(path("bad.exr"));
  for (float v : linear.data) EXPECT_TRUE(std::isfinite(v));
}

TEST_F(ImageFormats, Y4mHasHeaderAndPlanes) {
  Image im(4, 2, 3);
  im.data.assign(im.data.size(), 0.5f);
  write_image(path("a.y4m"), im);
  std::ifstream in(path("a.y4m"), std::ios::binary);
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header.rfind("YUV4MPEG2 W4 H2 F24:1", 0), 0u) << header;
  std::string frame;
  std::getline(in, frame);
  EXPECT_EQ(frame, "FRAME");
  std::string planes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(planes.size(), 8u + 2 + 2);  // 4:2:0: Y 4×2, Cb and Cr 2×1
  // Grey: Cb = Cr = 128 (limited range); Y = round(219·0.735357 + 16) = 177.
  EXPECT_EQ(uint8_t(planes[0]), 177);
  EXPECT_EQ(uint8_t(planes[8]), 128);

  // A sequence through the writer: two frames.
  DisplayImage frame_codes = develop(pixels_of(im), {});
  Y4mSettings thirty_fps;
  thirty_fps.fps_numerator = 30;
  Y4mWriter writer(path("seq.y4m"), 4, 2, thirty_fps);
  writer.write_frame(frame_codes);
  writer.write_frame(frame_codes);
  writer.close();
  EXPECT_EQ(fs::file_size(path("seq.y4m")), header.size() + 1 + 2 * (6 + 12));
  EXPECT_THROW(Y4mWriter(path("odd.y4m"), 3, 2), Error);
}

TEST_F(ImageFormats, UnsupportedPathsAreErrors) {
  Image im = sample();
  EXPECT_THROW(write_image(path("a.gif"), im), Error);
  EXPECT_THROW(write_image(path("missing/a.png"), im), Error);
  EXPECT_THROW(read_image(path("nothing.exr")), Error);
  EXPECT_FALSE(fs::exists(path("a.gif")));
}

}  // namespace
}  // namespace obscura
