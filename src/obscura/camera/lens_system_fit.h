// A lens system (focused_lens_system.h) measured by tracing and fitted with the calibrated
// camera's parametric models (calibrated_projection.h, lens_distortion.h): what the rasterizer
// draws a lens-system camera with, and what `obscura camera --export` writes for it.
//
// Measured along the sensor's diagonal, at image heights h from the centre to the corner (or to
// the image circle's rim when the lens's light ends before the corner; closer together towards
// it), at the d line:
//   * distortion: the field angle θ of the chief ray (through the stop's centre) on the object
//     side, against h;
//   * the entrance pupil: where each object-side chief ray, extended, crosses the axis. A real
//     lens has no single centre of projection: pupil aberration moves the crossing with the
//     field (by 1.8 mm over the double-Gauss's field, from its paraxial entrance pupil). The
//     fitted camera sits at the point c of the axis that minimizes the worst image displacement
//     this causes, max over h of sin θ · dh/dθ · |z(h) − c| (between the paraxial pupil and
//     the corner's crossing), and θ is measured from c to where the chief ray meets the plane
//     of focus: the fit is exact there and at every depth for a lens without pupil aberration;
//     elsewhere an object at distance D is off by up to parallax_px_m · |1/D − 1/S| pixels.
//     Focused at infinity, θ is the chief ray's direction;
//   * relative illumination: the mean of the tracer's ray weights (FocusedLensSystem::ray) over a
//     grid of pupil samples: cos⁴ fall-off, mechanical vignetting and the bellows factor, the
//     irradiance relative to the thin lens at the same f-number.
// Fitted, by linear least squares in the coefficients (QR, math/least_squares.h):
//   * a rectilinear lens: OpenCV's pinhole model, h = f·ρ·(1 + k1 ρ² + k2 ρ⁴ + k3 ρ⁶), ρ = tan θ
//     (f free: the basis ρ, ρ³, ρ⁵, ρ⁷);
//   * a fisheye (a field beyond 80°, or a rectilinear fit worse than the fisheye's):
//     Kannala–Brandt, h = f·θ·(1 + k1 θ² + k2 θ⁴ + k3 θ⁶ + k4 θ⁸), f free (basis θ, θ³, … θ⁹),
//     its field limited to the image circle;
//   * relative illumination: the measured table itself, linearly interpolated in h (mechanical
//     vignetting has a kink where a rim starts to cut the pupil, which a low-order polynomial
//     rounds off); its error is the interpolation's, measured at the midpoints.
#pragma once

#include <vector>

#include "obscura/camera/calibrated_projection.h"
#include "obscura/camera/camera.h"
#include "obscura/camera/focused_lens_system.h"
#include "obscura/math/vector.h"

namespace obscura {

// What tracing says at one image height along the diagonal (towards the upper-right corner).
struct LensFieldPoint {
  double image_height_mm = 0;
  double direction_angle_rad = 0;  // the object-side chief ray's angle from the optical axis
  // What the model is fitted to: the angle from the axis at which the centre of projection sees
  // the chief ray's point on the plane of focus (focused at infinity: direction_angle_rad).
  double field_angle_rad = 0;
  // Where the object-side chief ray, extended, crosses the axis: mm in front of the sensor.
  double pupil_distance_mm = 0;
  double relative_illumination = 0;  // the mean traced ray weight there (0: no light)
};

struct LensMeasurement {
  // From h = 0 to edge_height_mm, three times as close together at the edge as at the centre.
  std::vector<LensFieldPoint> field;
  // The half diagonal, or the image circle's radius when light ends before the corner.
  double edge_height_mm = 0;
  bool image_circle = false;  // the lens's light ends before the sensor's corner
  // Near the axis: image height per unit tan θ, and the chief rays' axis crossing (mm in front
  // of the sensor): the paraxial focal length at this focus, and the paraxial entrance pupil.
  double paraxial_focal_length_mm = 0;
  double entrance_pupil_distance_mm = 0;
  // The fitted camera's viewpoint on the axis, mm in front of the sensor (see the top).
  double centre_of_projection_mm = 0;
  // The traced chief rays' full angles across the image (degrees): horizontal, vertical and
  // diagonal, each out to the image's edge or the image circle, whichever is nearer.
  Vector3d fov_degrees;
};

struct LensFitSettings {
  int heights = 33;     // image heights measured, from the centre to the edge (≥ 8)
  int pupil_grid = 64;  // pupil_grid² ray weights averaged per height (64: within ~0.3 %)
  // Also trace the midpoints between the heights, for max_illumination_error (doubles the
  // tracing; renders leave it off).
  bool check_illumination = true;
};

// Traces `heights` image heights (≥ 8) and `pupil_grid`² pupil samples at each. Throws
// obscura::Error when no chief ray leaves the lens beyond the axis.
LensMeasurement measure_lens_system(const FocusedLensSystem& lens, int heights = 33,
                                    int pupil_grid = 64);

struct LensSystemFit {
  LensMeasurement measured;
  // K (pixels of a width_px × height_px film, OpenCV's conventions), the fitted lens model and,
  // for an image circle, the field limit.
  CalibratedProjection projection;
  // The distortion fit's residuals over the measured heights: |h_model(θ) − h| in pixels.
  double max_error_px = 0, rms_error_px = 0;
  // The illumination table's largest interpolation error (absolute, in relative illumination),
  // at the midpoints between its heights (0 unless LensFitSettings::check_illumination).
  double max_illumination_error = 0;
  // The largest distance (mm) of the chief rays' axis crossings from the centre of projection,
  // over the field: how far the real lens is from having one.
  double pupil_shift_mm = 0;
  // What that costs off the plane of focus: an object at distance D (m) lands up to
  // parallax_px_m · |1/D − 1/S| pixels from where the lens puts it (S the focus distance;
  // 1/S = 0 at infinity focus).
  double parallax_px_m = 0;
  // The fitted model's full angles (degrees): horizontal, vertical, diagonal.
  Vector3d fov_degrees;

  // The interpolated relative illumination at image height h (mm); 0 beyond the edge.
  double relative_illumination(double image_height_mm) const;
};

// Measures `lens` and fits the models for a film of width_px × height_px pixels covering its
// sensor (the sensor's size is in lens.settings()).
LensSystemFit fit_lens_system(const FocusedLensSystem& lens, int width_px, int height_px,
                              const LensFitSettings& settings = {});

// A lens-system camera's stand-in: a calibrated camera with the fitted model, at the centre of
// projection (so objects on the plane of focus land where the lens's chief rays put them), sharp
// (no depth of field), exposed at the lens system's f-number; and the fit, for its relative
// illumination.
struct FittedLensCamera {
  Camera camera;
  LensSystemFit fit;
  Vector2d sensor_mm;  // the lens system's sensor, which the camera's film covers
  // The relative illumination at raster point `film_point` of the camera's film.
  double relative_illumination(Point2d film_point) const;
};
// Throws obscura::Error unless `camera` has a lens-system projection.
FittedLensCamera fitted_lens_camera(const Camera& camera, const LensFitSettings& settings = {});

}  // namespace obscura
