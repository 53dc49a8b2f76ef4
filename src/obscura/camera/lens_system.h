// A lens system: a prescription (lens_prescription.h) laid out along its optical axis, ready to
// trace rays through surface by surface, with its first-order properties measured by tracing.
//
// Lens space: millimetres, the optical axis is z, pointing from the sensor towards the scene,
// with the rear surface's vertex at z = 0 (the front surfaces at larger z). Light from the scene
// travels towards −z; a camera traces the other way, from the film out into the scene.
//
// A ray ends where a real one would: outside a surface's clear aperture, outside the stop's
// opening, where it misses a curved surface, or by total internal reflection.
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "obscura/camera/aperture.h"
#include "obscura/camera/lens_prescription.h"
#include "obscura/math/vector.h"

namespace obscura {

struct LensRay {
  Point3d origin;      // mm, lens space
  Vector3d direction;  // unit
};

// The opening of the aperture stop a trace uses: its radius (the design's, or smaller when
// stopped down) and the blades' shape inscribed in that circle.
struct StopOpening {
  double radius_mm = 0;
  Aperture shape;
};

enum class TraceFrom { film, scene };

struct TraceOptions {
  double wavelength_nm = kWavelengthD_nm;
  // The stop's opening; nothing: the design's full circular stop.
  std::optional<StopOpening> stop;
  // Off: rays pass every clear aperture and the stop (a chief ray or a paraxial ray as a
  // construction, not as light).
  bool apertures = true;
  // Where the ray crossed the stop's plane, when asked.
  Point3d* at_stop = nullptr;
};

// One step of an explicit path through the lens (a ghost's, lens_ghosts.h): the surface met
// next, and whether the ray reflects off it or refracts through it. The direction of travel is
// the ray's own (towards −z: to the sensor; +z: back out to the scene).
struct SurfaceVisit {
  int surface = 0;
  bool reflect = false;
};

// What a sequence's ray met at one interface (the stop is no interface and is not listed): what
// a coating's reflectance needs.
struct InterfaceHit {
  int surface = 0;
  bool reflect = false;
  double cos_incidence = 1;     // of the ray with the surface's normal, in (0, 1]
  double n_from = 1, n_to = 1;  // the indices on the ray's side and on the far side
};

// The stop's opening as a sequence trace measures it.
struct StopGauge {
  double radius_mm = 0;
  ApertureGauge shape;
  explicit StopGauge(const StopOpening& stop) : radius_mm(stop.radius_mm), shape(stop.shape) {}
};

struct SequenceTrace {
  LensRay ray;  // after the last visit
  // How far outside the openings the ray went: the largest, over the visits, of the height over
  // the clear aperture's radius and of the stop opening's gauge (aperture_gauge). ≤ 1: nothing
  // stopped it. Not clipped during the trace, so that it can be interpolated between rays.
  double aperture_gauge = 0;
};

class LensSystem {
 public:
  // Validates the prescription (throws obscura::Error naming the surface and field) and measures
  // the first-order properties below.
  explicit LensSystem(LensPrescription prescription);

  const LensPrescription& prescription() const { return prescription_; }
  const std::string& name() const { return prescription_.name; }

  // The ray after the last (from the film: front) surface, or nothing where it is stopped.
  std::optional<LensRay> trace(LensRay ray, TraceFrom from, const TraceOptions& options = {}) const;
  // The ray through an explicit sequence of surfaces at `wavelength_nm` through `stop`, its
  // interfaces appended to `hits` when given (cleared first). Nothing where it misses a surface
  // or is totally reflected where it should refract; apertures do not end it (see
  // SequenceTrace::aperture_gauge). Through every surface in order without reflections, it is
  // trace(TraceFrom::scene) with the openings measured instead of applied.
  std::optional<SequenceTrace> trace_sequence(LensRay ray, std::span<const SurfaceVisit> sequence,
                                              double wavelength_nm, const StopGauge& stop,
                                              std::vector<InterfaceHit>* hits = nullptr) const;

  // First-order properties at the d line, measured by tracing near-axial rays (heights a
  // thousandth of the stop's radius; such rays follow the paraxial ABCD optics to ~1e-6):
  double effective_focal_length_mm() const { return efl_mm_; }
  // From the rear vertex to the rear focal point (towards the sensor, positive behind the lens).
  double back_focal_distance_mm() const { return bfd_mm_; }
  // From the front vertex to the front focal point (out into the scene).
  double front_focal_distance_mm() const { return ffd_mm_; }
  // The stop's image seen from the scene: its diameter.
  double entrance_pupil_diameter_mm() const { return entrance_pupil_mm_; }
  // EFL / entrance pupil diameter: the widest the lens opens (its design f-number).
  double f_number() const { return efl_mm_ / entrance_pupil_mm_; }
  double stop_radius_mm() const;
  // z of surface i's vertex (lens space), and the front vertex's.
  double vertex_z_mm(int surface) const { return vertex_z_[size_t(surface)]; }
  double front_z_mm() const { return vertex_z_.front(); }
  double rear_aperture_radius_mm() const;
  // The index of the medium in front of surface i (towards the scene) at `wavelength_nm`.
  double index_before(int surface, double wavelength_nm) const;
  // The index of the medium behind surface i (towards the sensor).
  double index_after(int surface, double wavelength_nm) const;

 private:
  LensPrescription prescription_;
  std::vector<double> vertex_z_;  // per surface
  // What each trace asks of surface i, computed once: the tests and divisions a ray would
  // otherwise repeat at every surface.
  struct TraceSurface {
    double curvature = 0;                          // 1 / radius (0: flat)
    double clear_radius2 = 0;                      // (clear aperture / 2)²
    double eta_from_film = 1, eta_from_scene = 1;  // n_in / n_out at the d line
    bool aspheric = false;
  };
  std::vector<TraceSurface> trace_surfaces_;
  int stop_ = 0;
  double efl_mm_ = 0, bfd_mm_ = 0, ffd_mm_ = 0, entrance_pupil_mm_ = 0;

  void measure_first_order();
};

}  // namespace obscura
