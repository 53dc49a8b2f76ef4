// Tagged PNGs: libpng itself (asked to keep the chunk it does not interpret) reads back the
// cICP chunk with the ITU-T H.273 code points written — Display P3 (12, 13, 0, 1), BT.2100 PQ
// (9, 16, 0, 1) and BT.2100 HLG (9, 18, 0, 1) — and an sRGB file carries the sRGB chunk instead.
// An HLG file's codes, read by libpng, are ITU-R BT.2100's HLG OETF of the scene light at its
// published points, with diffuse white at 75 % of the signal as ITU-R BT.2408 places it.
#include <gtest/gtest.h>
#include <png.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <vector>

#include "obscura/io/image_io.h"
#include "run_command.h"

namespace obscura {
namespace {

struct PngTags {
  std::optional<std::array<int, 4>> cicp;
  bool srgb = false;
};

PngTags read_tags(const std::string& path) {
  PngTags tags;
  FILE* file = std::fopen(path.c_str(), "rb");
  if (!file) return tags;
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png_create_info_struct(png);
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_read_struct(&png, &info, nullptr);
    std::fclose(file);
    return tags;
  }
  static const png_byte kName[] = "cICP";
  png_set_keep_unknown_chunks(png, PNG_HANDLE_CHUNK_ALWAYS, kName, 1);
  png_init_io(png, file);
  png_read_info(png, info);
  png_unknown_chunkp chunks = nullptr;
  const int count = png_get_unknown_chunks(png, info, &chunks);
  for (int i = 0; i < count; ++i)
    if (std::string(reinterpret_cast<const char*>(chunks[i].name)) == "cICP" && chunks[i].size == 4)
      tags.cicp = std::array<int, 4>{chunks[i].data[0], chunks[i].data[1], chunks[i].data[2],
                                     chunks[i].data[3]};
  int intent = 0;
  tags.srgb = png_get_sRGB(png, info, &intent) != 0;
  png_destroy_read_struct(&png, &info, nullptr);
  std::fclose(file);
  return tags;
}

class PngCicp : public test::TempDirTest {};

TEST_F(PngCicp, WideGamutAndPqFilesDeclareTheirSpace) {
  Image image(4, 4, 3);
  for (float& v : image.data) v = 0.25f;
  const struct {
    DisplaySpace space;
    std::optional<std::array<int, 4>> cicp;
    bool srgb;
  } cases[] = {{DisplaySpace::kSrgb, std::nullopt, true},
               {DisplaySpace::kDisplayP3, std::array<int, 4>{12, 13, 0, 1}, false},
               {DisplaySpace::kRec2020Pq, std::array<int, 4>{9, 16, 0, 1}, false},
               {DisplaySpace::kRec2020Hlg, std::array<int, 4>{9, 18, 0, 1}, false}};
  for (const auto& c : cases) {
    ImageWriteOptions options;
    options.display.display = c.space;
    options.display.bits = c.space == DisplaySpace::kSrgb ? 8 : 16;
    const std::string file = path("tagged.png");
    write_image(file, image, options);
    const PngTags tags = read_tags(file);
    EXPECT_EQ(tags.cicp, c.cicp) << int(c.space);
    EXPECT_EQ(tags.srgb, c.srgb) << int(c.space);
  }
}

// The first row of a 16-bit RGB PNG, as libpng reads it: the red sample of each pixel. (Everything
// the error path touches is made before setjmp; libpng longjmps back on a malformed file.)
std::vector<int> read_red_16(const std::string& path) {
  struct Closer {
    void operator()(FILE* f) const { std::fclose(f); }
  };
  const std::unique_ptr<FILE, Closer> file(std::fopen(path.c_str(), "rb"));
  if (!file) return {};
  std::array<png_byte, 4096> row{};
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png_create_info_struct(png);
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_read_struct(&png, &info, nullptr);
    return {};
  }
  png_init_io(png, file.get());
  png_read_info(png, info);
  const size_t bytes = png_get_rowbytes(png, info);
  const bool rgb16 =
      png_get_bit_depth(png, info) == 16 && png_get_color_type(png, info) == PNG_COLOR_TYPE_RGB;
  if (rgb16 && bytes <= row.size()) png_read_row(png, row.data(), nullptr);
  png_destroy_read_struct(&png, &info, nullptr);
  std::vector<int> reds;
  if (rgb16 && bytes <= row.size())
    for (size_t i = 0; i + 5 < bytes; i += 6) reds.push_back(row[i] << 8 | row[i + 1]);
  return reds;
}

TEST_F(PngCicp, HlgCodesFollowTheBt2100Oetf) {
  // BT.2100's HLG OETF with its constants a, b = 1 − 4a, c = 0.5 − a·ln(4a): E′ = √(3E) up to
  // E = 1/12 (E′ = 0.5 there), a·ln(12E − b) + c above (E′ = 1 at nominal peak E = 1).
  const double a = 0.17883277, b = 1 - 4 * a, c = 0.5 - a * std::log(4 * a);
  auto oetf = [&](double e) {
    return e <= 1.0 / 12 ? std::sqrt(3 * e) : a * std::log(12 * e - b) + c;
  };
  // BT.2408: diffuse white at 75 % of the HLG signal, i.e. the scene light E_w whose OETF is 0.75
  // (0.2650); the film's 1 is diffuse white, so film value v is E = v · E_w.
  const double white = (std::exp((0.75 - c) / a) + b) / 12;
  EXPECT_NEAR(white, 0.2650, 5e-5);
  const std::vector<double> scene_light = {0, 0.01, 1.0 / 12, white, 0.5, 1};
  const std::vector<double> published = {0, -1, 0.5, 0.75, -1, 1};  // -1: the formula only
  Image image(int(scene_light.size()), 1, 3);
  for (size_t i = 0; i < scene_light.size(); ++i)
    for (int ch = 0; ch < 3; ++ch) image.at(int(i), 0, ch) = float(scene_light[i] / white);
  ImageWriteOptions options;
  options.display.display = DisplaySpace::kRec2020Hlg;
  options.display.bits = 16;
  options.display.tonemap.op = ToneMap::kNone;  // light above diffuse white kept, up to the peak
  const std::string file = path("hlg.png");
  write_image(file, image, options);
  const std::vector<int> codes = read_red_16(file);
  ASSERT_EQ(codes.size(), scene_light.size());
  for (size_t i = 0; i < codes.size(); ++i) {
    // A grey stays a grey from Rec.709 to Rec.2020 (both D65): the red sample carries it.
    const double expected = oetf(scene_light[i]);
    if (published[i] >= 0) {
      EXPECT_NEAR(expected, published[i], 1e-6) << "E = " << scene_light[i];
    }
    EXPECT_NEAR(codes[i], expected * 65535, 1.0) << "E = " << scene_light[i];
  }
}

}  // namespace
}  // namespace obscura
