// How far apart two colours look: the CIEDE2000 colour difference (CIE 142-2001, ISO/CIE
// 11664-6) between two CIE L*a*b* colours, as Sharma, Wu and Dalal give it step by step ("The
// CIEDE2000 Color-Difference Formula: Implementation Notes, Supplementary Test Data, and
// Mathematical Observations", Color Research & Application 30(1), 2005), including their notes
// on the hue of a neutral (0) and the mean hue across 0°/360°.
#pragma once

#include "obscura/color/matrix3.h"

namespace obscura {

// The parametric weights kL, kC, kH (1, 1, 1: the reference conditions; textiles use kL = 2).
struct DeltaE2000Weights {
  double lightness = 1;
  double chroma = 1;
  double hue = 1;
};

// ΔE00 between L*a*b* colours (L in 0..100). Symmetric; 0 for equal colours. A difference of
// about 1 is the smallest most observers see side by side.
double delta_e_2000(const Vec3d& lab1, const Vec3d& lab2, const DeltaE2000Weights& weights = {});

}  // namespace obscura
