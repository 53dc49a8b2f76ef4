#include "obscura/camera/lens_ghosts.h"

namespace obscura {

namespace {

// A surface where light reflects: the index changes across it (at the d line).
bool is_interface(const LensSystem& lens, int surface) {
  return !lens.prescription().surfaces[size_t(surface)].is_stop &&
         lens.index_before(surface, kWavelengthD_nm) != lens.index_after(surface, kWavelengthD_nm);
}

double reflectance(const InterfaceHit& hit, const LensCoating& coating, double wavelength_nm) {
  // The coating lies on glass that faces air; cemented surfaces are bare.
  const bool faces_air = hit.n_from == 1 || hit.n_to == 1;
  return interface_reflectance(faces_air ? coating : LensCoating{}, hit.n_from, hit.n_to,
                               hit.cos_incidence, wavelength_nm);
}

}  // namespace

std::vector<Ghost> lens_ghosts(const LensSystem& lens) {
  const int count = int(lens.prescription().surfaces.size());
  std::vector<Ghost> ghosts;
  for (int i = 0; i < count; ++i) {
    if (!is_interface(lens, i)) continue;
    for (int j = 0; j < i; ++j)
      if (is_interface(lens, j)) ghosts.push_back({i, j});
  }
  return ghosts;
}

std::vector<SurfaceVisit> ghost_path(const LensSystem& lens, const Ghost& ghost) {
  const int count = int(lens.prescription().surfaces.size());
  std::vector<SurfaceVisit> path;
  for (int k = 0; k < ghost.first; ++k) path.push_back({k, false});
  path.push_back({ghost.first, true});
  for (int k = ghost.first - 1; k > ghost.second; --k) path.push_back({k, false});
  path.push_back({ghost.second, true});
  for (int k = ghost.second + 1; k < count; ++k) path.push_back({k, false});
  return path;
}

std::vector<SurfaceVisit> direct_path(const LensSystem& lens) {
  std::vector<SurfaceVisit> path;
  for (int k = 0; k < int(lens.prescription().surfaces.size()); ++k) path.push_back({k, false});
  return path;
}

double path_throughput(const std::vector<InterfaceHit>& hits, const LensCoating& coating,
                       double wavelength_nm) {
  double throughput = 1;
  for (const InterfaceHit& hit : hits) {
    if (hit.n_from == hit.n_to) continue;  // no interface: nothing reflects
    const double r = reflectance(hit, coating, wavelength_nm);
    throughput *= hit.reflect ? r : 1 - r;
  }
  return throughput;
}

std::optional<SensorHit> trace_to_sensor(const LensSystem& lens,
                                         const std::vector<SurfaceVisit>& path, const LensRay& ray,
                                         double film_distance_mm, double wavelength_nm,
                                         const StopGauge& stop, std::vector<InterfaceHit>& hits) {
  SensorHit out;
  std::optional<SequenceTrace> traced = lens.trace_sequence(ray, path, wavelength_nm, stop, &hits);
  // It must leave the rear towards the sensor.
  if (!traced || !(traced->ray.direction.z < 0)) return std::nullopt;
  const LensRay& r = traced->ray;
  const double t = (-film_distance_mm - r.origin.z) / r.direction.z;
  if (!(t >= 0)) return std::nullopt;
  out.sensor_mm = {r.origin.x + t * r.direction.x, r.origin.y + t * r.direction.y};
  out.aperture_gauge = traced->aperture_gauge;
  return out;
}

double axial_ghost_throughput(const LensSystem& lens, const Ghost& ghost,
                              const LensCoating& coating, double wavelength_nm) {
  std::vector<InterfaceHit> hits;
  for (const SurfaceVisit& visit : ghost_path(lens, ghost)) {
    const int i = visit.surface;
    hits.push_back({i, visit.reflect, 1, lens.index_before(i, wavelength_nm),
                    lens.index_after(i, wavelength_nm)});
  }
  return path_throughput(hits, coating, wavelength_nm);
}

}  // namespace obscura
