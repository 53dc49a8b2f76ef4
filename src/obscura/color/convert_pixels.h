// convert_color (color_space.h) over many pixels: the same double-precision functions, so the
// same values, without the per-pixel vectors of the one-colour API. RGB → RGB conversions (the
// common case: linear and encoded RGB spaces, any primaries) take a loop of their own: decode,
// the two matrices through XYZ-D65, encode, exactly as xyz_d65_from / from_xyz_d65 compute them.
// The input must be finite (the one-colour API checks; callers here check once for the array).
#pragma once
#include <cstddef>

#include "obscura/color/color_space.h"

namespace obscura {

// `in`: n pixels of from.components values; `out`: n pixels of to.components values. T is float
// or double; the arithmetic is double either way.
template <typename T>
void convert_pixels(const ColorSpaceInfo& from, const ColorSpaceInfo& to, const T* in, T* out,
                    size_t n);

}  // namespace obscura
