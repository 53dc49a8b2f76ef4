// The shading tables looked up with NaN (a NaN roughness texel, a NaN cosine from a light at
// 1e308): each lookup stays inside its table and reads the grid's first cell, as a cosine or
// roughness of 0 would. Before, int(NaN) indexed the tables at INT_MIN (SIGSEGV).
#include <gtest/gtest.h>

#include <limits>

#include "obscura/shading/charlie_sheen.h"
#include "obscura/shading/ggx_energy.h"

namespace obscura::shading {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

TEST(NanSafeLookups, GgxTablesReadTheFirstCellForNaN) {
  EXPECT_EQ(ggx_albedo(kNaN, 0.5f), ggx_albedo(0.f, 0.5f));
  EXPECT_EQ(ggx_albedo(0.5f, kNaN), ggx_albedo(0.5f, 0.f));
  EXPECT_EQ(ggx_albedo(kNaN, kNaN), ggx_albedo(0.f, 0.f));
  EXPECT_EQ(ggx_average_albedo(kNaN), ggx_average_albedo(0.f));
  EXPECT_EQ(ggx_schlick_albedo(0.04f, kNaN, kNaN), ggx_schlick_albedo(0.04f, 0.f, 0.f));
  EXPECT_EQ(ggx_schlick_average_albedo(0.04f, kNaN), ggx_schlick_average_albedo(0.04f, 0.f));
  // Infinities clamp to the grid's edges.
  EXPECT_EQ(ggx_albedo(kInf, kInf), ggx_albedo(1.f, 1.f));
  EXPECT_EQ(ggx_albedo(-kInf, -kInf), ggx_albedo(0.f, 0.f));
}

TEST(NanSafeLookups, SheenTableReadsTheFirstCellForNaN) {
  EXPECT_EQ(sheen_albedo(kNaN, 0.5f), sheen_albedo(0.f, 0.5f));
  EXPECT_EQ(sheen_albedo(0.5f, kNaN), sheen_albedo(0.5f, 0.f));
  EXPECT_EQ(sheen_albedo(kInf, kInf), sheen_albedo(1.f, 1.f));
}

}  // namespace
}  // namespace obscura::shading
