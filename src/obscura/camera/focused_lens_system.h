// A lens system set up in a camera: focused at a distance, its iris set, in front of a sensor of
// a given size. What a render asks of it per sample (a ray and its weight) uses what is computed
// here once: where the lens sits, and the bounds of the exit pupil seen from each film radius.
//
// Camera space is the camera's (camera.h): metres, looking down −Z, with its origin at the
// SENSOR (focus distances are measured from the sensor plane, as on a camera's focus scale, and
// depth too). The lens sits in front of it: lens space (lens_system.h) has z = −z_camera − d,
// with d the film distance (sensor to rear vertex), in millimetres.
//
// Image coordinates: millimetres on the sensor, x right and y up as the image is viewed (the
// screen window's orientation). A real lens forms an inverted image, so the light for image
// point (x, y) lands on the sensor at (−x, −y): the film point is flipped here.
//
// The ray weight makes an ideal lens expose like the thin-lens camera at the same f-number. The
// irradiance at a film point is E = L · ∫ cos θ · cos θ' / r² dA over the exit pupil; sampling a
// point of the pupil's bounds B (area |B|, on a plane d_p in front of the film) uniformly, with
// cos θ = cos θ' and r = d_p / cos θ, estimates E / L as cos⁴θ · |B| / d_p² (0 for a blocked
// ray). The thin lens with the exposure's f-number N collects π / (4 N²), so
//   weight = cos⁴θ · |B| / d_p² · 4 N² / π
// and the exposure (exposure.h) uses that same N. At the centre of an aberration-free lens
// focused at infinity the weight averages 1; elsewhere it carries the lens's natural (cos⁴) and
// mechanical vignetting.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "obscura/camera/aperture.h"
#include "obscura/camera/lens_system.h"
#include "obscura/math/vector.h"

namespace obscura {

struct LensSettings {
  double focus_distance_m = 10;  // > 0, from the sensor; ∞: infinity
  double f_number = 0;           // ≥ the lens's own (stops down); 0: wide open
  Aperture aperture;             // the iris's blades, inscribed in the stop's opening
  double sensor_width_mm = 36, sensor_height_mm = 24;
};
bool operator==(const LensSettings& a, const LensSettings& b);

// A ray leaving the front of the lens, in camera space.
struct LensCameraRay {
  Point3d origin;      // metres
  Vector3d direction;  // unit
  double weight = 1;
};

// The rectangle of the exit pupil's plane that a film point at (r, 0) sees light through.
struct PupilBounds {
  double x_min = 0, x_max = -1, y_min = 0, y_max = -1;  // mm; empty when min > max
  bool empty() const { return x_min > x_max || y_min > y_max; }
  double area() const { return empty() ? 0 : (x_max - x_min) * (y_max - y_min); }
};

class FocusedLensSystem {
 public:
  // Throws obscura::Error("camera.focus_distance_m", …) when the lens cannot focus that close,
  // and Error("camera.f_number", …) for an f-number below the lens's widest.
  FocusedLensSystem(std::shared_ptr<const LensSystem> lens, const LensSettings& settings);

  const LensSystem& lens() const { return *lens_; }
  const LensSettings& settings() const { return settings_; }
  double film_distance_mm() const { return film_distance_mm_; }  // sensor to rear vertex
  double f_number() const { return f_number_; }                  // the exposure's N
  const StopOpening& stop() const { return stop_; }

  // The ray for image point `image_mm` through the exit pupil's bounds at u ∈ [0,1)², traced at
  // `wavelength_nm`; nothing where the lens stops it.
  std::optional<LensCameraRay> ray(Point2d image_mm, Point2d u,
                                   double wavelength_nm = kWavelengthD_nm) const;
  // The chief ray of image point `image_mm`: the one through the centre of the stop (a
  // construction: clear apertures do not stop it). Its weight is 1.
  std::optional<LensCameraRay> chief_ray(Point2d image_mm,
                                         double wavelength_nm = kWavelengthD_nm) const;
  // The image point whose chief ray passes through `camera_point` (metres, camera space);
  // nothing when none does (behind the lens, beyond the lens's field).
  std::optional<Point2d> image_point_of(Point3d camera_point) const;

  // The exit pupil's bounds for film radius r (lens space, on the plane z = 0 of the rear
  // vertex, for a film point on the +x axis), and whether a lens-space ray from that film point
  // through pupil point p reaches the scene: what the bounds were made of.
  PupilBounds pupil_bounds(double film_radius_mm) const;
  bool passes(double film_radius_mm, Point2d pupil_point_mm) const;

 private:
  std::shared_ptr<const LensSystem> lens_;
  LensSettings settings_;
  double film_distance_mm_ = 0, f_number_ = 0;
  StopOpening stop_;
  double max_film_radius_mm_ = 0;
  std::vector<PupilBounds> bounds_;  // per film-radius interval

  double solve_film_distance(double focus_distance_mm) const;
  double best_focus(double focus_distance_mm, double paraxial_mm) const;
  void compute_pupil_bounds();
  std::optional<LensRay> chief_ray_lens(double film_radius_mm, double wavelength_nm) const;
  LensCameraRay to_camera(const LensRay& ray) const;
};

// The focused lens for `settings`, made once per thread and kept while the settings stay the
// same (a camera's rays, project and unproject calls each ask for it).
std::shared_ptr<const FocusedLensSystem> focused_lens_system(
    const std::shared_ptr<const LensSystem>& lens, const LensSettings& settings);

}  // namespace obscura
