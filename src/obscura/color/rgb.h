// Linear RGB triples: radiance, reflectance, pixel values. The working space is linear Rec.709
// (sRGB primaries, D65 white) unless a caller says otherwise.
#pragma once

#include <algorithm>

namespace obscura {

struct Rgb {
  float r = 0, g = 0, b = 0;

  constexpr Rgb() = default;
  constexpr Rgb(float r_, float g_, float b_) : r(r_), g(g_), b(b_) {}
  constexpr explicit Rgb(float v) : r(v), g(v), b(v) {}

  constexpr float operator[](int i) const { return i == 0 ? r : (i == 1 ? g : b); }
  constexpr float& operator[](int i) { return i == 0 ? r : (i == 1 ? g : b); }
  constexpr Rgb operator+(Rgb o) const { return {r + o.r, g + o.g, b + o.b}; }
  constexpr Rgb operator-(Rgb o) const { return {r - o.r, g - o.g, b - o.b}; }
  constexpr Rgb operator*(Rgb o) const { return {r * o.r, g * o.g, b * o.b}; }
  constexpr Rgb operator*(float s) const { return {r * s, g * s, b * s}; }
  constexpr Rgb operator/(float s) const { return {r / s, g / s, b / s}; }
  constexpr Rgb& operator+=(Rgb o) { return *this = *this + o; }
  constexpr Rgb& operator*=(Rgb o) { return *this = *this * o; }
  constexpr Rgb& operator*=(float s) { return *this = *this * s; }
  constexpr bool operator==(const Rgb&) const = default;

  constexpr bool is_black() const { return r == 0 && g == 0 && b == 0; }
  constexpr float max_component() const { return std::max(r, std::max(g, b)); }
};

constexpr Rgb operator*(float s, Rgb c) { return c * s; }

// Relative luminance Y of linear Rec.709 RGB (the middle row of its RGB→XYZ matrix).
constexpr float luminance(Rgb c) { return 0.2126729f * c.r + 0.7151522f * c.g + 0.0721750f * c.b; }

}  // namespace obscura
