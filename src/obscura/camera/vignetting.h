// Vignetting of the thin lens: the darkening towards the image's corners, in two physically
// derived parts, each switchable (docs/camera.md, "Vignetting").
//
// Natural: a film point seeing the aperture along a chief ray at angle θ to the axis receives
// cos⁴θ of the axial irradiance: one cos for the film's tilt to the light, one for the
// aperture's foreshortening and two for the inverse square of the longer distance (the
// small-aperture limit of the exact integral over the aperture, which differs from it by
// O((A/2v)²)). For a perspective camera tanθ = |w|, w the window point (X/Z, Y/Z), so
//   E(θ)/E(0) = cos⁴θ = 1 / (1 + |w|²)².
//
// Mechanical: the lens barrel (its front element) is a second circular opening of diameter B at
// distance D in front of the aperture. A lens point l (in the aperture plane) sends its ray
// towards the focus point w·S_f (S_f the focus distance), which crosses the barrel's plane at
//   l·(1 − D/S_f) + w·D,
// and the light is kept only where that lies within B/2 of the axis. In the aperture plane the
// kept points are the aperture intersected with a disc of radius (B/2)/(1 − D/S_f) centred at
// −w·D/(1 − D/S_f): off axis, two overlapping discs, the cat-eye shape of off-axis bokeh. On
// the axis the barrel (B ≥ A, validated) clips nothing, so the image centre keeps its exposure.
#pragma once

#include <array>
#include <utility>

#include "obscura/camera/aperture.h"
#include "obscura/math/vector.h"

namespace obscura {

struct Vignetting {
  bool natural = false;  // cos⁴θ
  // Mechanical (the cat-eye): 0 = no barrel; otherwise ≥ the aperture diameter.
  double barrel_diameter_mm = 0;
  double barrel_distance_mm = 0;  // in front of the aperture, ≥ 0 and short of the focus plane

  bool mechanical() const { return barrel_diameter_mm > 0; }
  bool any() const { return natural || mechanical(); }
};

// cos⁴θ of the chief ray through window point w: 1 / (1 + |w|²)².
double natural_vignetting(Point2d window);

// Whether the ray from `lens_point_mm` (the aperture plane, camera x right, y up) towards the
// focus point of window point `window` passes the barrel. True without a barrel.
// `focus_distance_mm` may be infinite.
bool passes_barrel(const Vignetting& v, Point2d lens_point_mm, Point2d window,
                   double focus_distance_mm);

// The aperture's vertical chords at the abscissas barrel_transmission integrates over (128
// strips across the unit circle), computed once per aperture.
struct ApertureChords {
  static constexpr int kStrips = 128;
  std::array<std::pair<double, double>, kStrips> chords;  // [low, high]; low > high: none
};
ApertureChords aperture_chords(const Aperture& aperture);

// The share of the aperture (radius `aperture_radius_mm`, chords of its shape) whose rays
// towards window point w's focus point pass the barrel: the light mechanical vignetting leaves
// there, in [0, 1]; 1 without a barrel. Integrated over the chords (~2e-3).
double barrel_transmission(const Vignetting& v, const ApertureChords& aperture,
                           double aperture_radius_mm, Point2d window, double focus_distance_mm);

// Throws obscura::Error naming the field for a negative or non-finite value, a barrel narrower
// than the aperture diameter, or one at or beyond the focus distance.
void validate(const Vignetting& v, double aperture_diameter_mm, double focus_distance_mm);

}  // namespace obscura
