#include "obscura/camera/lens_system.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "obscura/math/error.h"

namespace obscura {

namespace {

// Where the ray meets the surface whose vertex is at z = vertex_z, as the distance t along the
// ray; nothing when it misses. Spheres and planes are solved exactly; an asphere starts from
// its base sphere's (or plane's) solution and refines t by Newton's method on the sag equation
// z(t) − vertex_z + sag(r(t)) = 0.
std::optional<double> intersect(const LensSurface& s, bool aspheric, double vertex_z,
                                const LensRay& ray) {
  const Point3d& o = ray.origin;
  const Vector3d& d = ray.direction;
  double t;
  if (s.radius_mm == 0) {
    if (d.z == 0) return std::nullopt;
    t = (vertex_z - o.z) / d.z;
  } else {
    // The sphere through the vertex with its centre `radius` towards the sensor (−z).
    Vector3d oc = o - Point3d(0, 0, vertex_z - s.radius_mm);
    double b = dot(oc, d);
    double c = dot(oc, oc) - s.radius_mm * s.radius_mm;
    double discriminant = b * b - c;
    if (discriminant < 0) return std::nullopt;
    double root = std::sqrt(discriminant);
    // The cap around the vertex: the far side of the sphere when the ray travels towards the
    // vertex's side of the centre, the near side otherwise.
    t = (d.z > 0) == (s.radius_mm > 0) ? -b + root : -b - root;
  }
  if (aspheric) {
    constexpr int kMaxIterations = 30;
    constexpr double kTolerance_mm = 1e-12;
    bool converged = false;
    for (int i = 0; i < kMaxIterations && !converged; ++i) {
      Point3d p = o + d * t;
      double r = std::hypot(p.x, p.y);
      Sag sag;
      if (!surface_sag(s, r, sag)) return std::nullopt;
      double g = p.z - vertex_z + sag.z;
      double dr_dt = r > 0 ? (p.x * d.x + p.y * d.y) / r : 0;
      double dg_dt = d.z + sag.slope * dr_dt;
      if (dg_dt == 0) return std::nullopt;
      double step = g / dg_dt;
      t -= step;
      converged = std::abs(step) < kTolerance_mm;
    }
    if (!converged) return std::nullopt;
  }
  // Behind the ray: missed. A surface the ray has just left may touch the next one (a stop
  // plane at a convex vertex, 0 mm apart): there the distance is the sag, ~1e-11 mm for a chief
  // ray, and rounding can make it negative; a hair of slack keeps such rays.
  constexpr double kTouching_mm = 1e-9;
  if (!(t >= -kTouching_mm) || !std::isfinite(t)) return std::nullopt;
  return std::max(t, 0.0);
}

// The unit normal of the surface at p, facing against `d` (the side the ray comes from).
std::optional<Vector3d> facing_normal(const LensSurface& s, Point3d p, Vector3d d) {
  double r = std::hypot(p.x, p.y);
  Sag sag;
  if (!surface_sag(s, r, sag)) return std::nullopt;
  // The surface is z = vertex_z − sag(r); its gradient (∂/∂x, ∂/∂y, ∂/∂z) of z + sag(r).
  Vector3d n = r > 0 ? Vector3d(sag.slope * p.x / r, sag.slope * p.y / r, 1) : Vector3d(0, 0, 1);
  n = n / length(n);
  return dot(n, d) < 0 ? n : -n;
}

// The same for a sphere or a plane, without the sag: a sphere's unit normal is (p − centre)/R
// (the centre R towards the sensor from the vertex), which is the sag's gradient direction
// (c·x, c·y, √(1 − c²r²)) with c = 1/R, already of unit length.
Vector3d facing_normal_spherical(const LensSurface& s, double curvature, double vertex_z, Point3d p,
                                 Vector3d d) {
  Vector3d n(0, 0, 1);
  if (s.radius_mm != 0)
    n = Vector3d(p.x * curvature, p.y * curvature, (p.z - vertex_z + s.radius_mm) * curvature);
  return dot(n, d) < 0 ? n : -n;
}

// Snell's law for unit d and unit n facing against it, with η = n_in / n_out; nothing by total
// internal reflection.
std::optional<Vector3d> refract(Vector3d d, Vector3d n, double eta) {
  double cos_i = -dot(n, d);
  double sin2_t = eta * eta * (1 - cos_i * cos_i);
  if (sin2_t > 1) return std::nullopt;
  double cos_t = std::sqrt(1 - sin2_t);
  // |t|² = η²(1 − cos²θi) + cos²θt = sin²θt + cos²θt = 1: unit to rounding, no normalizing.
  return d * eta + n * (eta * cos_i - cos_t);
}

}  // namespace

LensSystem::LensSystem(LensPrescription prescription) : prescription_(std::move(prescription)) {
  validate(prescription_);
  stop_ = stop_index(prescription_);
  const auto& surfaces = prescription_.surfaces;
  vertex_z_.assign(surfaces.size(), 0);
  for (int i = int(surfaces.size()) - 2; i >= 0; --i)
    vertex_z_[size_t(i)] = vertex_z_[size_t(i) + 1] + surfaces[size_t(i)].thickness_mm;
  for (int i = 0; i < int(surfaces.size()); ++i) {
    const LensSurface& s = surfaces[size_t(i)];
    TraceSurface& t = trace_surfaces_.emplace_back();
    t.curvature = s.radius_mm != 0 ? 1 / s.radius_mm : 0;
    t.clear_radius2 = 0.25 * s.aperture_diameter_mm * s.aperture_diameter_mm;
    t.eta_from_film = index_after(i, kWavelengthD_nm) / index_before(i, kWavelengthD_nm);
    t.eta_from_scene = 1 / t.eta_from_film;
    t.aspheric = s.is_aspheric();
  }
  measure_first_order();
}

double LensSystem::stop_radius_mm() const {
  return 0.5 * prescription_.surfaces[size_t(stop_)].aperture_diameter_mm;
}

double LensSystem::rear_aperture_radius_mm() const {
  return 0.5 * prescription_.surfaces.back().aperture_diameter_mm;
}

double LensSystem::index_after(int surface, double wavelength_nm) const {
  const LensSurface& s = prescription_.surfaces[size_t(surface)];
  if (wavelength_nm == kWavelengthD_nm) return s.n_d;
  return refractive_index(s.n_d, s.abbe_number, wavelength_nm);
}

double LensSystem::index_before(int surface, double wavelength_nm) const {
  return surface == 0 ? 1 : index_after(surface - 1, wavelength_nm);
}

std::optional<LensRay> LensSystem::trace(LensRay ray, TraceFrom from,
                                         const TraceOptions& options) const {
  const auto& surfaces = prescription_.surfaces;
  const int count = int(surfaces.size());
  const bool from_film = from == TraceFrom::film;
  for (int k = 0; k < count; ++k) {
    const int i = from_film ? count - 1 - k : k;
    const LensSurface& s = surfaces[size_t(i)];
    const TraceSurface& surface = trace_surfaces_[size_t(i)];
    // 1. Where the ray meets the surface.
    std::optional<double> t = intersect(s, surface.aspheric, vertex_z_[size_t(i)], ray);
    if (!t) return std::nullopt;
    Point3d p = ray.origin + ray.direction * *t;
    // 2. Stopped outside the clear aperture, or outside the stop's opening.
    double r2 = p.x * p.x + p.y * p.y;
    if (s.is_stop) {
      if (options.at_stop) *options.at_stop = p;
      if (options.apertures) {
        if (!options.stop) {
          if (r2 > surface.clear_radius2) return std::nullopt;
        } else {
          const double scale = 1 / options.stop->radius_mm;
          if (!aperture_contains(options.stop->shape, {p.x * scale, p.y * scale}))
            return std::nullopt;
        }
      }
      ray.origin = p;
      continue;
    }
    if (options.apertures && r2 > surface.clear_radius2) return std::nullopt;
    // 3. Refraction into the next medium.
    std::optional<Vector3d> n =
        surface.aspheric
            ? facing_normal(s, p, ray.direction)
            : facing_normal_spherical(s, surface.curvature, vertex_z_[size_t(i)], p, ray.direction);
    if (!n) return std::nullopt;
    double eta = from_film ? surface.eta_from_film : surface.eta_from_scene;
    if (options.wavelength_nm != kWavelengthD_nm)
      eta = from_film
                ? index_after(i, options.wavelength_nm) / index_before(i, options.wavelength_nm)
                : index_before(i, options.wavelength_nm) / index_after(i, options.wavelength_nm);
    std::optional<Vector3d> refracted = refract(ray.direction, *n, eta);
    if (!refracted) return std::nullopt;
    ray = {p, *refracted};
  }
  return ray;
}

std::optional<SequenceTrace> LensSystem::trace_sequence(LensRay ray,
                                                        std::span<const SurfaceVisit> sequence,
                                                        double wavelength_nm, const StopGauge& stop,
                                                        std::vector<InterfaceHit>* hits) const {
  if (hits) hits->clear();
  const auto& surfaces = prescription_.surfaces;
  double gauge = 0;
  for (const SurfaceVisit& visit : sequence) {
    const int i = visit.surface;
    const LensSurface& s = surfaces[size_t(i)];
    // 1. Where the ray meets the surface, and how far outside its opening.
    const TraceSurface& ts = trace_surfaces_[size_t(i)];
    std::optional<double> t = intersect(s, ts.aspheric, vertex_z_[size_t(i)], ray);
    if (!t) return std::nullopt;
    const Point3d p = ray.origin + ray.direction * *t;
    if (s.is_stop) {
      gauge = std::max(gauge, stop.shape({p.x / stop.radius_mm, p.y / stop.radius_mm}));
      ray.origin = p;
      continue;
    }
    gauge = std::max(gauge, std::sqrt(p.x * p.x + p.y * p.y) / (0.5 * s.aperture_diameter_mm));
    // 2. The media on either side, by the direction of travel.
    std::optional<Vector3d> n =
        ts.aspheric
            ? facing_normal(s, p, ray.direction)
            : facing_normal_spherical(s, ts.curvature, vertex_z_[size_t(i)], p, ray.direction);
    if (!n) return std::nullopt;
    const bool towards_sensor = ray.direction.z < 0;
    const double before = index_before(i, wavelength_nm), after = index_after(i, wavelength_nm);
    const double n_from = towards_sensor ? before : after, n_to = towards_sensor ? after : before;
    const double cos_i = -dot(*n, ray.direction);
    if (hits) hits->push_back({i, visit.reflect, cos_i, n_from, n_to});
    // 3. Reflected (the mirror direction) or refracted.
    if (visit.reflect) {
      ray = {p, ray.direction + *n * (2 * cos_i)};
    } else {
      std::optional<Vector3d> refracted = refract(ray.direction, *n, n_from / n_to);
      if (!refracted) return std::nullopt;
      ray = {p, *refracted};
    }
  }
  return SequenceTrace{ray, gauge};
}

void LensSystem::measure_first_order() {
  const std::string lens = "lens '" + name() + "'";
  // Near-axial rays behave as paraxial ones: the angles are ~1e-4, so the sines and tangents
  // of the exact trace differ from the angles by ~1e-8 relative.
  const double h = 1e-4 * stop_radius_mm();
  TraceOptions construction;
  construction.apertures = false;
  Point3d at_stop;
  construction.at_stop = &at_stop;
  // A ray parallel to the axis from the scene: its exit slope gives the focal length, its axis
  // crossing the rear focal point, its height at the stop the entrance pupil.
  auto from_scene = trace({{0, h, front_z_mm() + 1}, {0, 0, -1}}, TraceFrom::scene, construction);
  if (!from_scene || from_scene->direction.y == 0)
    throw Error(lens, "a ray parallel to the axis does not pass through it (an afocal lens?)");
  const LensRay& out = *from_scene;
  double slope = out.direction.y / -out.direction.z;  // height change per mm towards the sensor
  efl_mm_ = -h / slope;
  bfd_mm_ = -(out.origin.z - out.origin.y / out.direction.y * out.direction.z);
  if (at_stop.y == 0) throw Error(lens, "the axial ray does not reach the stop");
  entrance_pupil_mm_ = std::abs(2 * stop_radius_mm() * h / at_stop.y);
  if (!(efl_mm_ > 0))
    throw Error(lens, "is not a converging lens (effective focal length " +
                          std::to_string(efl_mm_) + " mm); a camera needs one");
  // The same from the sensor side: the front focal point.
  auto from_film = trace({{0, h, -1}, {0, 0, 1}}, TraceFrom::film, construction);
  if (!from_film || from_film->direction.y == 0)
    throw Error(lens, "a ray parallel to the axis from the sensor does not pass through it");
  const LensRay& back = *from_film;
  ffd_mm_ = back.origin.z - back.origin.y / back.direction.y * back.direction.z - front_z_mm();
}

}  // namespace obscura
