#include "obscura/color/tonemap.h"

#include <algorithm>

#include "obscura/math/error.h"

namespace obscura {

std::string tone_map_name(ToneMap t) {
  switch (t) {
    case ToneMap::kNone:
      return "none";
    case ToneMap::kClamp:
      return "clamp";
    case ToneMap::kReinhard:
      return "reinhard";
    case ToneMap::kAces:
      return "aces";
    case ToneMap::kHable:
      return "hable";
  }
  return "?";
}

ToneMap parse_tone_map(const std::string& name) {
  for (ToneMap t :
       {ToneMap::kNone, ToneMap::kClamp, ToneMap::kReinhard, ToneMap::kAces, ToneMap::kHable})
    if (tone_map_name(t) == name) return t;
  throw Error("tonemap",
              "unknown operator '" + name + "'; expected none, clamp, reinhard, aces or hable");
}

namespace {

float hable_partial(float x) {
  // Shoulder strength, linear strength, linear angle, toe strength, toe numerator, denominator.
  constexpr float a = 0.15f, b = 0.50f, c = 0.10f, d = 0.20f, e = 0.02f, f = 0.30f;
  return (x * (a * x + c * b) + d * e) / (x * (a * x + b) + d * f) - e / f;
}

}  // namespace

float tone_map(float x, const ToneMapSettings& s) {
  if (s.op == ToneMap::kNone || s.op == ToneMap::kClamp)
    return s.op == ToneMap::kNone ? x : std::min(x, 1.f);
  x = std::max(x, 0.f);  // tone curves are defined for light, not for negative values
  switch (s.op) {
    case ToneMap::kNone:
      return x;
    case ToneMap::kClamp:
      return std::min(x, 1.f);
    case ToneMap::kReinhard: {
      float w2 = s.reinhard_white * s.reinhard_white;
      return std::min(x * (1 + x / w2) / (1 + x), 1.f);
    }
    case ToneMap::kAces: {
      // Narkowicz's fit expects the ACES exposure convention, where scene grey sits 0.6 lower.
      float v = 0.6f * x;
      return std::clamp(v * (2.51f * v + 0.03f) / (v * (2.43f * v + 0.59f) + 0.14f), 0.f, 1.f);
    }
    case ToneMap::kHable: {
      constexpr float kWhite = 11.2f, kExposureBias = 2.f;
      static const float white_scale = 1 / hable_partial(kWhite);
      return std::min(hable_partial(kExposureBias * x) * white_scale, 1.f);
    }
  }
  return x;
}

Rgb tone_map(Rgb c, const ToneMapSettings& s) {
  return {tone_map(c.r, s), tone_map(c.g, s), tone_map(c.b, s)};
}

}  // namespace obscura
