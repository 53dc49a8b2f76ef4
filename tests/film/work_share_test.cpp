// The deal of a frame's tiles between the parts that render it together: every pixel belongs to
// exactly one part, the parts' packed pixels put the frame back together exactly, and the
// round-robin deal keeps the parts' loads even. Checked against a brute-force count over every
// pixel, not against the deal's own iteration.
#include "obscura/film/work_share.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <limits>
#include <vector>

#include "obscura/math/error.h"

namespace obscura {
namespace {

struct DealCase {
  int width, height, tile_size, parts;
};

// Sizes that are and are not multiples of the tile, single pixels and single rows or columns,
// and more parts than there are tiles.
std::vector<DealCase> deal_cases() {
  std::vector<DealCase> cases;
  const int sizes[][2] = {{1, 1}, {1, 17}, {17, 1}, {16, 16}, {64, 48}, {65, 49}, {100, 3}};
  for (const auto& size : sizes)
    for (int tile_size : {1, 5, 16, 64})
      for (int parts : {1, 2, 3, 5, 7, 64, 1000})
        cases.push_back({size[0], size[1], tile_size, parts});
  return cases;
}

std::string describe(const DealCase& c) {
  return std::to_string(c.width) + "x" + std::to_string(c.height) + ", tiles of " +
         std::to_string(c.tile_size) + ", " + std::to_string(c.parts) + " parts";
}

// The owner of pixel (x, y) worked out from the definition: tiles numbered row by row, tile t
// to part t mod parts.
int expected_owner(const DealCase& c, int x, int y) {
  const int columns = (c.width + c.tile_size - 1) / c.tile_size;
  const int tile = (y / c.tile_size) * columns + x / c.tile_size;
  return tile % c.parts;
}

TEST(WorkShareDeal, EveryPixelBelongsToExactlyOnePart) {
  for (const DealCase& c : deal_cases()) {
    SCOPED_TRACE(describe(c));
    const TileDeal deal{
        .width = c.width, .height = c.height, .tile_size = c.tile_size, .parts = c.parts};
    // Count, for each pixel, how many parts' packets carry it: pack an image whose pixels hold
    // their own index and tally the indices each part sends.
    Image index_image(c.width, c.height, 1);
    for (size_t i = 0; i < index_image.data.size(); ++i) index_image.data[i] = float(i);
    std::vector<int> carriers(index_image.data.size(), 0);
    std::vector<int> carrier_part(index_image.data.size(), -1);
    size_t counted = 0;
    for (int part = 0; part < c.parts; ++part) {
      const std::vector<float> packed = pack_owned_pixels(deal, part, index_image);
      ASSERT_EQ(packed.size(), deal.pixel_count(part)) << "part " << part;
      counted += deal.pixel_count(part);
      for (float index : packed) {
        ++carriers[size_t(index)];
        carrier_part[size_t(index)] = part;
      }
    }
    EXPECT_EQ(counted, size_t(c.width) * c.height);
    for (int y = 0; y < c.height; ++y)
      for (int x = 0; x < c.width; ++x) {
        const size_t i = size_t(y) * c.width + x;
        ASSERT_EQ(carriers[i], 1) << "pixel " << x << "," << y;
        ASSERT_EQ(carrier_part[i], expected_owner(c, x, y)) << "pixel " << x << "," << y;
        ASSERT_EQ(deal.owner(x, y), expected_owner(c, x, y)) << "pixel " << x << "," << y;
      }
  }
}

TEST(WorkShareDeal, PartsWithoutTilesOwnNoPixels) {
  // A 1×1 frame is one tile: part 0 owns it, every other part nothing.
  const TileDeal deal{.width = 1, .height = 1, .tile_size = 16, .parts = 4};
  EXPECT_EQ(deal.pixel_count(0), 1u);
  Image image(1, 1, 3);
  for (int part = 1; part < 4; ++part) {
    EXPECT_EQ(deal.pixel_count(part), 0u);
    EXPECT_TRUE(pack_owned_pixels(deal, part, image).empty());
  }
}

TEST(WorkShareDeal, PackingEveryPartAndUnpackingReassemblesTheImageExactly) {
  for (const DealCase& c : deal_cases()) {
    SCOPED_TRACE(describe(c));
    const TileDeal deal{
        .width = c.width, .height = c.height, .tile_size = c.tile_size, .parts = c.parts};
    // Three channels of distinct values, special ones (NaN, ±∞, −0, denormals) among them: the
    // reassembly must move bits, not values.
    Image original(c.width, c.height, 3);
    const float specials[] = {
        std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(),
        -std::numeric_limits<float>::infinity(), -0.f, std::numeric_limits<float>::denorm_min()};
    for (size_t i = 0; i < original.data.size(); ++i)
      original.data[i] = i % 7 == 3 ? specials[(i / 7) % 5] : float(i) * 0.37f - 11.f;
    Image assembled(c.width, c.height, 3);
    std::fill(assembled.data.begin(), assembled.data.end(), 12345.f);
    // Parts in reverse order: the assembly does not depend on the order the packets arrive in.
    for (int part = c.parts - 1; part >= 0; --part)
      unpack_owned_pixels(deal, part, pack_owned_pixels(deal, part, original), assembled);
    ASSERT_EQ(std::memcmp(assembled.data.data(), original.data.data(),
                          original.data.size() * sizeof(float)),
              0);
  }
}

TEST(WorkShareDeal, UnpackingTouchesOnlyThePartsPixels) {
  const TileDeal deal{.width = 40, .height = 33, .tile_size = 16, .parts = 3};
  Image source(40, 33, 2);
  std::fill(source.data.begin(), source.data.end(), 1.f);
  Image target(40, 33, 2);
  unpack_owned_pixels(deal, 1, pack_owned_pixels(deal, 1, source), target);
  for (int y = 0; y < 33; ++y)
    for (int x = 0; x < 40; ++x)
      for (int ch = 0; ch < 2; ++ch)
        ASSERT_EQ(target.at(x, y, ch), deal.owner(x, y) == 1 ? 1.f : 0.f) << x << "," << y;
}

TEST(WorkShareDeal, UnpackRefusesAPacketOfTheWrongSize) {
  const TileDeal deal{.width = 40, .height = 33, .tile_size = 16, .parts = 3};
  Image image(40, 33, 4);
  std::vector<float> packed = pack_owned_pixels(deal, 2, image);
  ASSERT_FALSE(packed.empty());
  std::vector<float> short_by_one(packed.begin(), packed.end() - 1);
  EXPECT_THROW(unpack_owned_pixels(deal, 2, short_by_one, image), Error);
  std::vector<float> long_by_one = packed;
  long_by_one.push_back(0.f);
  EXPECT_THROW(unpack_owned_pixels(deal, 2, long_by_one, image), Error);
  // Another part's packet has another size here (part 0 owns one tile more).
  EXPECT_THROW(unpack_owned_pixels(deal, 2, pack_owned_pixels(deal, 0, image), image), Error);
  // Packed from an image with fewer channels: the right pixel count, too few values.
  Image rgb(40, 33, 3);
  EXPECT_THROW(unpack_owned_pixels(deal, 2, pack_owned_pixels(deal, 2, rgb), image), Error);
  // An image of another size than the frame is refused both ways.
  Image small(39, 33, 4);
  EXPECT_THROW(pack_owned_pixels(deal, 2, small), Error);
  EXPECT_THROW(unpack_owned_pixels(deal, 2, packed, small), Error);
}

TEST(WorkShareDeal, RoundRobinKeepsThePartsWithinOneTileOfEachOther) {
  const TileDeal base{.width = 512, .height = 512, .tile_size = 16, .parts = 1};
  const int tiles = (512 / 16) * (512 / 16);
  for (int parts = 2; parts <= 8; ++parts) {
    TileDeal deal = base;
    deal.parts = parts;
    for (int part = 0; part < parts; ++part) {
      // Every tile of this frame is whole, so a part's tiles are its pixels / 256.
      const size_t owned_tiles = deal.pixel_count(part) / (16 * 16);
      EXPECT_EQ(deal.pixel_count(part) % (16 * 16), 0u);
      EXPECT_LE(owned_tiles, size_t(tiles / parts + 1)) << part << " of " << parts;
      EXPECT_GE(owned_tiles, size_t(tiles / parts)) << part << " of " << parts;
    }
  }
}

TEST(WorkShare, AgreeUsesTheTeamsVerdictWhenThereIsOne) {
  WorkShare alone;
  EXPECT_TRUE(alone.alone());
  EXPECT_EQ(alone.agree(StopVerdict::kTimeLimit), StopVerdict::kTimeLimit);
  int calls = 0;
  WorkShare member{.part = 1, .parts = 3, .settle = [&](StopVerdict own) {
                     ++calls;
                     return std::max(own, StopVerdict::kTimeLimit);
                   }};
  EXPECT_FALSE(member.alone());
  EXPECT_EQ(member.agree(StopVerdict::kGoOn), StopVerdict::kTimeLimit);
  EXPECT_EQ(member.agree(StopVerdict::kCancelled), StopVerdict::kCancelled);
  EXPECT_EQ(calls, 2);
  EXPECT_TRUE(member.owns_tile(1));
  EXPECT_TRUE(member.owns_tile(4));
  EXPECT_FALSE(member.owns_tile(3));
}

}  // namespace
}  // namespace obscura
