// NaN-safe indices: every input, NaN and infinities included, lands inside the table.
#include "obscura/math/safe_index.h"

#include <gtest/gtest.h>

#include <limits>

namespace obscura {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

TEST(SafeIndex, ClampSendsNaNToTheLowEnd) {
  EXPECT_EQ(clamp_or_low(kNaN, 0.f, 31.f), 0.f);
  EXPECT_EQ(clamp_or_low(-kInf, 0.f, 31.f), 0.f);
  EXPECT_EQ(clamp_or_low(kInf, 0.f, 31.f), 31.f);
  EXPECT_EQ(clamp_or_low(12.5f, 0.f, 31.f), 12.5f);
  EXPECT_EQ(clamp_or_low(std::numeric_limits<double>::quiet_NaN(), -1.0, 1.0), -1.0);
}

TEST(SafeIndex, CellIndexStaysInsideTheGrid) {
  EXPECT_EQ(cell_index(kNaN, 64), 0);
  EXPECT_EQ(cell_index(-kInf, 64), 0);
  EXPECT_EQ(cell_index(kInf, 64), 63);
  EXPECT_EQ(cell_index(1e30f, 64), 63);
  EXPECT_EQ(cell_index(-3.f, 64), 0);
  EXPECT_EQ(cell_index(5.9f, 64), 5);
}

TEST(SafeIndex, FloorToIndexIsFloorWithinRangeAndBoundedOutside) {
  EXPECT_EQ(floor_to_index(2.7f), 2);
  EXPECT_EQ(floor_to_index(-2.2f), -3);
  EXPECT_EQ(floor_to_index(kNaN), 0);
  EXPECT_EQ(floor_to_index(1e30f), 1 << 30);
  EXPECT_EQ(floor_to_index(-kInf), -(1 << 30));
  // A neighbour one further still fits an int.
  EXPECT_GT(floor_to_index(kInf) + 1, 0);
}

}  // namespace
}  // namespace obscura
