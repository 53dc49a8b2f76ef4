// Transfer functions: published values and exact inverses.
#include "obscura/color/transfer.h"

#include <cmath>

#include <gtest/gtest.h>

#include "obscura/math/error.h"

namespace obscura {
namespace {

constexpr TransferFunction kAll[] = {TransferFunction::kLinear,  TransferFunction::kSrgb,
                                     TransferFunction::kBt709,   TransferFunction::kBt1886,
                                     TransferFunction::kGamma22, TransferFunction::kPq,
                                     TransferFunction::kHlg};

TEST(Transfer, InversesWithin1e6OverUnitRangeAndNegatives) {
  for (TransferFunction f : kAll)
    for (int i = -1000; i <= 1000; ++i) {
      double v = i / 1000.0;
      EXPECT_NEAR(decode(f, encode(f, v)), v, 1e-6) << transfer_function_name(f) << " at " << v;
      EXPECT_NEAR(encode(f, decode(f, v)), v, 1e-6) << transfer_function_name(f) << " at " << v;
    }
}

TEST(Transfer, HdrCurvesInvertBeyondOne) {
  for (TransferFunction f : {TransferFunction::kPq, TransferFunction::kHlg})
    for (double v = 1; v <= 50; v *= 1.1)
      EXPECT_NEAR(decode(f, encode(f, v)) / v, 1, 1e-6) << transfer_function_name(f) << " " << v;
  // PQ signals above 1 (beyond 10 000 cd/m²) decode back too, up to the curve's asymptote.
  for (double e = 1; e < 1.5; e += 0.05)
    EXPECT_NEAR(encode(TransferFunction::kPq, decode(TransferFunction::kPq, e)), e, 1e-6);
}

TEST(Transfer, PublishedValues) {
  // sRGB: mid grey 0.18 → 0.4613561 (IEC 61966-2-1 formula); the break at 0.0031308 → 0.04045.
  EXPECT_NEAR(encode(TransferFunction::kSrgb, 0.18), 0.46135612950044164, 1e-9);
  EXPECT_NEAR(encode(TransferFunction::kSrgb, 0.0031308), 0.040449936, 1e-8);
  // BT.709: 4.5·L below β; 1 → 1.
  EXPECT_NEAR(encode(TransferFunction::kBt709, 0.01), 0.045, 1e-12);
  EXPECT_NEAR(encode(TransferFunction::kBt709, 1.0), 1.0, 1e-9);
  // PQ (ST 2084): 100 cd/m² → 0.5081 (BT.2100 / ITU-R BT.2408 tables), 10 000 → 1, 0 → 7.3e-7.
  EXPECT_NEAR(encode(TransferFunction::kPq, 0.01), 0.50807, 1e-4);
  EXPECT_NEAR(encode(TransferFunction::kPq, 1.0), 1.0, 1e-12);
  EXPECT_NEAR(encode(TransferFunction::kPq, 203.0 / 10000), 0.58069, 1e-4);  // BT.2408 white
  // HLG (BT.2100): 1/12 → 0.5 exactly, 1 → 1.
  EXPECT_NEAR(encode(TransferFunction::kHlg, 1.0 / 12), 0.5, 1e-12);
  EXPECT_NEAR(encode(TransferFunction::kHlg, 1.0), 1.0, 1e-7);
  // Pure powers.
  EXPECT_NEAR(decode(TransferFunction::kBt1886, 0.5), std::pow(0.5, 2.4), 1e-15);
  EXPECT_NEAR(decode(TransferFunction::kGamma22, 0.5), std::pow(0.5, 2.2), 1e-15);
}

TEST(Transfer, CurvesAreContinuousAtTheirBreaks) {
  // The piecewise curves must meet where their segments join (BT.2020's α, β are chosen so).
  const double beta = 0.018053968510807;
  EXPECT_NEAR(encode(TransferFunction::kBt709, beta - 1e-12),
              encode(TransferFunction::kBt709, beta + 1e-12), 1e-9);
  EXPECT_NEAR(encode(TransferFunction::kHlg, 1.0 / 12 - 1e-12),
              encode(TransferFunction::kHlg, 1.0 / 12 + 1e-12), 1e-9);
}

TEST(Transfer, NamesRoundTripAndUnknownNameIsAnError) {
  for (TransferFunction f : kAll) EXPECT_EQ(parse_transfer_function(transfer_function_name(f)), f);
  EXPECT_THROW(parse_transfer_function("gamma3"), Error);
}

}  // namespace
}  // namespace obscura
