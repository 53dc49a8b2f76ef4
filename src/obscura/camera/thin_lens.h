// The thin lens: depth of field. A lens of focal length f, opened to diameter A = f / N, focused
// at distance S_f, forms a sharp image of the plane at S_f on the sensor, which then sits at the
// image distance v = f·S_f / (S_f − f) behind the lens (1/f = 1/S_f + 1/v). A point at depth S
// images to a disk, the circle of confusion, of diameter
//   c = A · |S − S_f| / S · f / (S_f − f)        (on the sensor, same units as A)
// Because the sensor sits at v rather than f, a lens focused close sees slightly less than at
// infinity focus ("focus breathing"), as real lenses do; at S_f = ∞ the framing is the pinhole's.
// With focus_breathing off the sensor stays at f whatever the focus, so the framing is the
// pinhole's at every focus distance (the convention of Blender Cycles and pbrt), and then
//   c = A · |S − S_f| / S · f / S_f.
#pragma once

#include <optional>

#include "obscura/camera/aperture.h"
#include "obscura/camera/vignetting.h"

namespace obscura {

struct ThinLens {
  // Off: a pinhole, everything sharp (f_number still sets the physical exposure).
  bool depth_of_field = false;
  double f_number = 8;  // N > 0; aperture diameter = focal length / N
  // > 0 when given; overrides f_number (then N = focal length / diameter).
  std::optional<double> aperture_diameter_mm;
  double focus_distance_m = 10;  // S_f > focal length, measured from the lens along its axis
  // On: the sensor sits at the image distance v (a physical lens). Off: at f, the framing of
  // renderers that keep the field of view fixed (Cycles, pbrt), to match their images.
  bool focus_breathing = true;
  Aperture aperture;
  // Natural (cos⁴) and mechanical (lens barrel, cat-eye) vignetting; off by default.
  Vignetting vignetting;
};

// A = f / N, or the given diameter.
double aperture_diameter_mm(const ThinLens& lens, double focal_length_mm);
// N = f / A.
double effective_f_number(const ThinLens& lens, double focal_length_mm);
// v = f·S_f / (S_f − f), in mm.
double image_distance_mm(double focal_length_mm, double focus_distance_m);
// c = A · |S − S_f| / S · f / (S_f − f) (or · f / S_f without focus breathing), in mm on the
// sensor, for a point at depth S (metres along the optical axis, > 0). Zero when depth of field
// is off.
double circle_of_confusion_mm(const ThinLens& lens, double focal_length_mm, double depth_m);

// Throws obscura::Error naming the first invalid parameter and its value. The focus distance
// must exceed the focal length (nothing closer can be focused).
void validate(const ThinLens& lens, double focal_length_mm);

}  // namespace obscura
