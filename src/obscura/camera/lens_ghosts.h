// Ghosts: the images a lens forms of a bright light by reflections between its surfaces. Light
// from the scene enters the front, reflects back at surface i, forwards again at an earlier
// surface j < i (surfaces numbered from the front), then passes the rest of the lens to the
// sensor. Every pair of the lens's interfaces (surfaces with a change of index; the stop is
// none) makes one ghost: N·(N − 1)/2 of them for N interfaces. Paths with more than two
// reflections carry the square of these ghosts' already small share and are left out, as are
// reflections off the sensor and the barrel.
//
// A ghost ray's throughput is the product, over the interfaces it meets, of the transmittance
// 1 − R where it passes and the reflectance R where it reflects, each at the ray's own angle of
// incidence and wavelength (lens_coating.h): so coatings weaken ghosts and colour them.
#pragma once

#include <optional>
#include <vector>

#include "obscura/camera/lens_coating.h"
#include "obscura/camera/lens_system.h"

namespace obscura {

struct Ghost {
  int first = 0;   // i: the surface that reflects the light back first (the later one)
  int second = 0;  // j < i: the surface that sends it forwards again
};

// Every ghost of the lens, ordered by (first, second).
std::vector<Ghost> lens_ghosts(const LensSystem& lens);

// The surfaces a ghost's light meets from the front to the sensor: 0 … i (reflect at i),
// i − 1 … j (reflect at j), j + 1 … last. The direct image's path: every surface once.
std::vector<SurfaceVisit> ghost_path(const LensSystem& lens, const Ghost& ghost);
std::vector<SurfaceVisit> direct_path(const LensSystem& lens);

// The share of the light a traced path delivers: Π (1 − R) over the passes × Π R over the
// reflections, unpolarised, with `coating` on every interface between air (index 1) and glass.
double path_throughput(const std::vector<InterfaceHit>& hits, const LensCoating& coating,
                       double wavelength_nm);

// A ray of a path as far as the sensor plane (lens space z = −film_distance_mm), its
// interfaces in `hits` (reused between rays: no allocation per ray).
struct SensorHit {
  Point2d sensor_mm;          // lens-space x, y on the sensor (the image is inverted there)
  double aperture_gauge = 0;  // ≤ 1: no opening stopped it (SequenceTrace)
};
std::optional<SensorHit> trace_to_sensor(const LensSystem& lens,
                                         const std::vector<SurfaceVisit>& path, const LensRay& ray,
                                         double film_distance_mm, double wavelength_nm,
                                         const StopGauge& stop, std::vector<InterfaceHit>& hits);

// A ghost's throughput for light along the axis at normal incidence on every surface (its
// size in a listing; real rays meet the surfaces obliquely): R_i·R_j times the transmittances of
// the interfaces passed.
double axial_ghost_throughput(const LensSystem& lens, const Ghost& ghost,
                              const LensCoating& coating, double wavelength_nm = 550);

}  // namespace obscura
