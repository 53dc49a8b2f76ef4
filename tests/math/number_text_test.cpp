#include "obscura/math/number_text.h"

#include <gtest/gtest.h>

#include <limits>

namespace obscura {
namespace {

TEST(NumberText, IntegersHaveNoDecimals) {
  EXPECT_EQ(number_text(-1), "-1");
  EXPECT_EQ(number_text(0), "0");
  EXPECT_EQ(number_text(1920), "1920");
}

TEST(NumberText, FractionsKeepTenSignificantDigitsWithoutTrailingZeros) {
  EXPECT_EQ(number_text(0.5), "0.5");
  EXPECT_EQ(number_text(39.59775), "39.59775");
  EXPECT_EQ(number_text(1.0 / 3.0), "0.3333333333");
}

TEST(NumberText, InfinityReadsAsInf) {
  EXPECT_EQ(number_text(std::numeric_limits<double>::infinity()), "inf");
  EXPECT_EQ(number_text(-std::numeric_limits<double>::infinity()), "-inf");
}

}  // namespace
}  // namespace obscura
