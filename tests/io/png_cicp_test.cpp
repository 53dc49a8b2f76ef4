// Tagged PNGs: libpng itself (asked to keep the chunk it does not interpret) reads back the
// cICP chunk with the ITU-T H.273 code points written — Display P3 (12, 13, 0, 1) and BT.2100
// PQ (9, 16, 0, 1) — and an sRGB file carries the sRGB chunk instead.
#include <gtest/gtest.h>
#include <png.h>

#include <array>
#include <cstdio>
#include <optional>

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
               {DisplaySpace::kRec2020Pq, std::array<int, 4>{9, 16, 0, 1}, false}};
  for (const auto& c : cases) {
    ImageWriteOptions options;
    options.display.display = c.space;
    options.display.bits = c.space == DisplaySpace::kRec2020Pq ? 16 : 8;
    const std::string file = path("tagged.png");
    write_image(file, image, options);
    const PngTags tags = read_tags(file);
    EXPECT_EQ(tags.cicp, c.cicp) << int(c.space);
    EXPECT_EQ(tags.srgb, c.srgb) << int(c.space);
  }
}

}  // namespace
}  // namespace obscura
