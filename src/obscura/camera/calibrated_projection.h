// The projection of a calibrated camera: intrinsics K in pixels (OpenCV's conventions) and a lens
// model (lens_distortion.h), as a calibration toolbox reports them. A film point is turned into a
// ray by the lens model's inverse map, exactly, for every sample; a ray lands on the film by its
// forward map.
//
// Pixel coordinates (u, v) are OpenCV's: integer pixel centres, y down, on an image of
// `width_px` × `height_px` (the calibration's size). Obscura's raster coordinates put pixel
// centres at half-integers, so raster = (u + ½, v + ½) · (film size / calibration size): a render
// at another resolution scales K, as resizing a photograph does.
//   u = fx · x' + skew · y' + cx,   v = fy · y' + cy
// with (x', y') the lens model's normalized image point.
#pragma once

#include "obscura/camera/lens_distortion.h"

namespace obscura {

struct Intrinsics {
  double fx = 0, fy = 0;  // focal length in pixels, > 0
  double cx = 0, cy = 0;  // principal point, pixels (integer pixel centres)
  double skew = 0;        // K[0][1]: pixels per unit of y' added to u (0 for square sensors)
  bool operator==(const Intrinsics&) const = default;
};

struct CalibratedProjection {
  Intrinsics k;
  int width_px = 0, height_px = 0;  // the calibration's image size; 0: the film's
  LensModel lens = PinholeDistortion{};
  // Half the widest field the lens sees (degrees from the axis; 100 for a 200° fisheye); 0: the
  // lens model's own validity limit.
  double max_field_angle_degrees = 0;
};

// Throws obscura::Error naming the first invalid field (fx, fy ≤ 0, non-finite values, a lens
// model without a valid region, a field angle outside (0, 180]).
void validate(const CalibratedProjection& p);

// The lens map of `p` (its validity region found once per thread and lens, then reused: cameras
// that project many points one call at a time stay cheap).
const LensMap& lens_map(const CalibratedProjection& p);

// The field-angle limit lens maps use, in radians (0: the model's own).
double max_field_angle_rad(const CalibratedProjection& p);

}  // namespace obscura
