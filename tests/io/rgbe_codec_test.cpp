// Radiance HDR (RGBE) against its definition (Ward, "Real Pixels", Graphics Gems II; the
// Radiance file format): a pixel is mantissas R, G, B and a shared exponent E, each channel
// mantissa × 2^(E − 136); the encoder picks E so the largest channel's mantissa is in
// [128, 256), and 0 is all zeros. Encodings below are worked by hand from that definition.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "obscura/io/image_codecs_loader.h"
#include "obscura/io/image_reader.h"
#include "obscura/math/error.h"
#include "test_files.h"

namespace obscura {
namespace {

using test::error_of;
using test::file_bytes;
using test::put_file;

std::vector<unsigned char> encode_floats(int width, int height, const std::vector<float>& rgb) {
  EncodeRequest r;
  r.path = "t.hdr";
  r.width = width;
  r.height = height;
  r.channels = 3;
  r.data = rgb.data();
  return image_codecs().encode(r);
}

std::vector<float> decode_floats(const std::vector<unsigned char>& file, int* width = nullptr,
                                 int* height = nullptr) {
  CheckedImageInput in = CheckedImageInput::open_memory(file, "t.hdr", "");
  if (width) *width = in.header().width;
  if (height) *height = in.header().height;
  std::vector<float> out(size_t(in.header().width) * size_t(in.header().height) * 3);
  in.read(3, SampleType::kFloat, out.data());
  return out;
}

std::vector<unsigned char> file_with(const std::string& header, std::vector<unsigned char> body) {
  std::vector<unsigned char> file(header.begin(), header.end());
  file.insert(file.end(), body.begin(), body.end());
  return file;
}

// The bytes after the header (which ends with the resolution line).
std::vector<unsigned char> pixels_of(const std::vector<unsigned char>& file) {
  std::string text(file.begin(), file.end());
  size_t at = text.find("+X ");
  at = text.find('\n', at);
  return {file.begin() + long(at + 1), file.end()};
}

TEST(Rgbe, FlatPixelsEncodeAsWorkedByHand) {
  // Width 2 (< 8): flat pixels. 1 = 0.5·2¹ → E = 129, mantissa 1·256/2 = 128; 0.5 → 64;
  // 0.25 → 32. 3 = 0.75·2² → E = 130, mantissa 3·256/4 = 192. Black: all zeros.
  auto file = encode_floats(2, 2,
                            {1.f, 0.5f, 0.25f, /**/ 3.f, 0.f, 0.f,
                             /**/ 0.f, 0.f, 0.f, /**/ 0.001f, 0.002f, 0.f});
  // 0.002 = 0.512·2⁻⁸ → E = 120; 0.002·256·2⁸ = 131.07 → 131; 0.001 → 65.5 → 65.
  EXPECT_EQ(pixels_of(file), (std::vector<unsigned char>{128, 64, 32, 129, 192, 0, 0, 130, 0, 0, 0,
                                                         0, 65, 131, 0, 120}));
  EXPECT_EQ(std::string(file.begin(), file.begin() + 11), "#?RADIANCE\n");
}

TEST(Rgbe, DecodingIsMantissaTimesTwoToTheExponentMinus136) {
  auto file = file_with("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 3\n",
                        {200, 100, 50, 140, /**/ 255, 0, 1, 120, /**/ 9, 9, 9, 0});
  std::vector<float> f = decode_floats(file);
  // 2^(140−136) = 16; 2^(120−136) = 2⁻¹⁶; E = 0 is black whatever the mantissas.
  EXPECT_EQ(f, (std::vector<float>{3200.f, 1600.f, 800.f, 255.f / 65536.f, 0.f, 1.f / 65536.f, 0.f,
                                   0.f, 0.f}));
}

TEST(Rgbe, ScanlinesOf8OrMorePixelsUseTheAdaptiveRunLengthForm) {
  // Ten pixels of (1, 0.5, 0.25) = (128, 64, 32, 129): each component one run of ten,
  // (128 + 10, value), after the scanline's mark 2, 2, width >> 8, width & 255.
  std::vector<float> row;
  for (int i = 0; i < 10; ++i) row.insert(row.end(), {1.f, 0.5f, 0.25f});
  auto file = encode_floats(10, 1, row);
  EXPECT_EQ(pixels_of(file),
            (std::vector<unsigned char>{2, 2, 0, 10, 138, 128, 138, 64, 138, 32, 138, 129}));
  EXPECT_EQ(decode_floats(file), row);
}

TEST(Rgbe, RoundTripsWithinTheEncodingsPrecision) {
  std::vector<float> rgb;
  for (int i = 0; i < 40 * 3 * 3; ++i) rgb.push_back(std::pow(1.37f, float(i % 41) - 20.f));
  int w = 0, h = 0;
  std::vector<float> back = decode_floats(encode_floats(40, 3, rgb), &w, &h);
  EXPECT_EQ(w, 40);
  EXPECT_EQ(h, 3);
  for (size_t p = 0; p < rgb.size() / 3; ++p) {
    float largest = std::max({rgb[3 * p], rgb[3 * p + 1], rgb[3 * p + 2]});
    for (int c = 0; c < 3; ++c)  // truncation: at most one step of 2^(E−136) ≤ largest / 128
      EXPECT_NEAR(back[3 * p + c], rgb[3 * p + c], largest / 128.f) << p << " " << c;
  }
}

TEST(Rgbe, TheOldRunLengthFormRepeatsThePreviousPixel) {
  // (1, 1, 1, n) repeats the previous pixel n times; a second in a row repeats n << 8.
  auto file = file_with("#?RGBE\n\n-Y 1 +X 4\n", {128, 0, 0, 129, /**/ 1, 1, 1, 3});
  std::vector<float> f = decode_floats(file);
  for (int x = 0; x < 4; ++x) EXPECT_EQ(f[3 * size_t(x)], 1.f) << x;
  // +Y: the first scanline in the file is the bottom row.
  auto flipped = file_with("#?RADIANCE\n\n+Y 2 +X 1\n", {128, 0, 0, 129, /**/ 0, 128, 0, 129});
  EXPECT_EQ(decode_floats(flipped), (std::vector<float>{0.f, 1.f, 0.f, 1.f, 0.f, 0.f}));
}

TEST(Rgbe, HostileHeadersAndRunsAreErrorsNotAllocationsOrOverruns) {
  // A huge declared size is refused by the size check before anything is decoded.
  auto huge = file_with("#?RADIANCE\n\n-Y 1000000 +X 1000000\n", {});
  EXPECT_NE(
      error_of([&] { CheckedImageInput::open_memory(huge, "huge.hdr", ""); }).find("huge.hdr"),
      std::string::npos);
  // A run longer than its scanline.
  auto overrun = file_with("#?RADIANCE\n\n-Y 1 +X 8\n", {2, 2, 0, 8, 128 + 100, 7});
  EXPECT_NE(error_of([&] { decode_floats(overrun); }).find("overruns"), std::string::npos);
  // A scanline whose mark names another width.
  auto width = file_with("#?RADIANCE\n\n-Y 1 +X 8\n", {2, 2, 0, 9});
  EXPECT_NE(error_of([&] { decode_floats(width); }).find("width"), std::string::npos);
  // A repeat with nothing before it, and a missing resolution line, and XYZE.
  auto repeat = file_with("#?RADIANCE\n\n-Y 1 +X 2\n", {1, 1, 1, 1, 1, 1, 1, 1});
  EXPECT_NE(error_of([&] { decode_floats(repeat); }).find("repeat"), std::string::npos);
  auto no_size = file_with("#?RADIANCE\n\n", {});
  EXPECT_NE(error_of([&] { decode_floats(no_size); }).find("t.hdr"), std::string::npos);
  auto xyze = file_with("#?RADIANCE\nFORMAT=32-bit_rle_xyze\n\n-Y 1 +X 1\n", {0, 0, 0, 0});
  EXPECT_NE(error_of([&] { decode_floats(xyze); }).find("32-bit_rle_rgbe"), std::string::npos);
  // A header that never ends.
  std::string endless = "#?RADIANCE\n" + std::string(70000, 'x');
  auto long_header = file_with(endless, {});
  EXPECT_NE(error_of([&] { decode_floats(long_header); }).find("64 KiB"), std::string::npos);
}

}  // namespace
}  // namespace obscura
