#include "obscura/io/image_io.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "obscura/color/srgb.h"
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
      for (int c = 0; c < 3; ++c)
        EXPECT_EQ(raw[(row * 5 + x) * 3 + c], image.at(x, 2 - row, c));
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

}  // namespace
}  // namespace obscura
