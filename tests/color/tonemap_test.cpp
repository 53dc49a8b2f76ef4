// Tone mapping operators: anchors each operator is built around, monotonicity, names.
#include "obscura/color/tonemap.h"

#include <gtest/gtest.h>

#include "obscura/math/error.h"

namespace obscura {
namespace {

constexpr ToneMap kCurves[] = {ToneMap::kClamp, ToneMap::kReinhard, ToneMap::kAces,
                               ToneMap::kHable};

TEST(ToneMap, BlackStaysBlackAndCurvesRiseToAtMostOne) {
  for (ToneMap op : kCurves) {
    ToneMapSettings s{.op = op};
    EXPECT_NEAR(tone_map(0.f, s), 0.f, 1e-6f) << tone_map_name(op);
    float previous = 0;
    for (float x = 0.001f; x < 1000; x *= 1.05f) {
      float y = tone_map(x, s);
      EXPECT_GE(y, previous) << tone_map_name(op) << " at " << x;
      EXPECT_LE(y, 1.f);
      previous = y;
    }
    EXPECT_GT(tone_map(1000.f, s), 0.99f) << tone_map_name(op) << " saturates to white";
  }
}

TEST(ToneMap, ReinhardMapsItsWhitePointToOne) {
  for (float white : {1.f, 4.f, 16.f}) {
    ToneMapSettings s{.op = ToneMap::kReinhard, .reinhard_white = white};
    EXPECT_NEAR(tone_map(white, s), 1.f, 1e-6f);
    EXPECT_LT(tone_map(0.5f * white, s), 1.f);
  }
  // With an infinite white point it is the classic x/(1+x): 1 → ½.
  EXPECT_NEAR(tone_map(1.f, {.op = ToneMap::kReinhard, .reinhard_white = 1e30f}), 0.5f, 1e-6f);
}

TEST(ToneMap, HableReachesWhiteAtItsWhitePoint) {
  // White 11.2 after the exposure bias of 2: scene value 5.6 is display white.
  EXPECT_NEAR(tone_map(5.6f, {.op = ToneMap::kHable}), 1.f, 1e-5f);
  EXPECT_LT(tone_map(5.0f, {.op = ToneMap::kHable}), 1.f);
}

TEST(ToneMap, FilmicCurvesCompressHighlightsMoreThanShadows) {
  // A filmic curve has a toe and a shoulder: the slope at 4 is far below the slope at 0.18.
  for (ToneMap op : {ToneMap::kAces, ToneMap::kHable, ToneMap::kReinhard}) {
    ToneMapSettings s{.op = op};
    auto slope = [&](float x) { return (tone_map(x * 1.01f, s) - tone_map(x, s)) / (0.01f * x); };
    EXPECT_LT(slope(4.f), 0.3f * slope(0.18f)) << tone_map_name(op);
  }
}

TEST(ToneMap, NoneAndClampKeepNegativesForTheGamutStep) {
  EXPECT_EQ(tone_map(-0.25f, {.op = ToneMap::kNone}), -0.25f);
  EXPECT_EQ(tone_map(7.f, {.op = ToneMap::kNone}), 7.f);
  EXPECT_EQ(tone_map(7.f, {.op = ToneMap::kClamp}), 1.f);
}

TEST(ToneMap, NamesRoundTripAndUnknownIsAnError) {
  for (ToneMap op :
       {ToneMap::kNone, ToneMap::kClamp, ToneMap::kReinhard, ToneMap::kAces, ToneMap::kHable})
    EXPECT_EQ(parse_tone_map(tone_map_name(op)), op);
  EXPECT_THROW(parse_tone_map("filmic-blender"), Error);
}

}  // namespace
}  // namespace obscura
