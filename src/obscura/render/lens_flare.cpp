#include "obscura/render/lens_flare.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <variant>

#include "obscura/camera/lens_system_projection.h"
#include "obscura/color/cie_tables.h"
#include "obscura/color/spectral_working_space.h"
#include "obscura/film/ray_grid_splat.h"
#include "obscura/math/error.h"
#include "obscura/math/number_text.h"
#include "obscura/trace/punctual_light.h"

namespace obscura {

namespace {

constexpr double kMillimetresPerMetre = 1000;
constexpr double kSquareMetresPerSquareMillimetre = 1e-6;
// The three traced wavelengths, each the centre of a 100 nm band; the colour within a band is
// resolved every 10 nm.
constexpr int kBands = 3;
constexpr int kStepsPerBand = 10;
constexpr double kFirstNm = 400, kBandNm = 100, kStepNm = kBandNm / kStepsPerBand;
constexpr int kRowsPerTask = 16;  // the splatting's row bands

double band_centre_nm(int band) {
  return kFirstNm + (band + 0.5) * kBandNm;
}
double step_nm(int band, int step) {
  return kFirstNm + band * kBandNm + (step + 0.5) * kStepNm;
}

using ChannelWeights = std::array<std::array<std::array<double, 3>, kStepsPerBand>, kBands>;

// Per 10 nm step, the linear Rec.709 response max(0, RGB_from_XYZ · x̄ȳz̄(λ)) of each channel,
// normalised so that each channel's weights sum to 1 over 400–700 nm.
const ChannelWeights& channel_weights() {
  static const ChannelWeights weights = [] {
    ChannelWeights w{};
    std::array<double, 3> total{};
    const SpectralTable& cmf = cie1931_cmf();
    for (int b = 0; b < kBands; ++b)
      for (int s = 0; s < kStepsPerBand; ++s) {
        const int row = int(std::lround(step_nm(b, s) - 0.5)) - cmf.first_nm;
        const Vec3d rgb =
            working_rgb_from_xyz() * Vec3d{cmf.at(row, 0), cmf.at(row, 1), cmf.at(row, 2)};
        for (int c = 0; c < 3; ++c) {
          w[size_t(b)][size_t(s)][size_t(c)] = std::max(0.0, rgb[size_t(c)]);
          total[size_t(c)] += w[size_t(b)][size_t(s)][size_t(c)];
        }
      }
    for (auto& band : w)
      for (auto& step : band)
        for (int c = 0; c < 3; ++c) step[size_t(c)] /= total[size_t(c)];
    return w;
  }();
  return weights;
}

// What the flare needs of a lens-system camera, computed once.
struct FlareOptics {
  std::shared_ptr<const FocusedLensSystem> focused;
  const LensSystem* lens = nullptr;
  StopGauge stop{StopOpening{}};
  LensCoating coating;
  Transform camera_from_world;
  double sensor_width_mm = 0, sensor_height_mm = 0;
  int width_px = 0, height_px = 0;
  Bounds2i crop;
  // Power (W) on the sensor → the film's units × pixel area: 1/(pixel area) in m⁻², times the
  // camera equation's 4N²/π and the exposure.
  double film_per_watt = 0;
  double front_radius_mm = 0;

  explicit FlareOptics(const Camera& camera) {
    const auto* projection = std::get_if<LensSystemProjection>(&camera.projection);
    if (!projection)
      throw Error("flare", "needs a lens-system camera (its surfaces make the ghosts)");
    focused = focused_lens_system(projection->lens, camera.lens_system_settings());
    lens = &focused->lens();
    stop = StopGauge(focused->stop());
    coating = projection->coating;
    camera_from_world = inverse(camera.world_from_camera.at(camera.shutter.time_at(0.5)));
    sensor_width_mm = focused->settings().sensor_width_mm;
    sensor_height_mm = focused->settings().sensor_height_mm;
    width_px = camera.film.width_px, height_px = camera.film.height_px;
    crop = camera.film.crop_pixels();
    const double pixel_area_m2 = sensor_width_mm / width_px * sensor_height_mm / height_px *
                                 kSquareMetresPerSquareMillimetre;
    const double n = focused->f_number();
    film_per_watt = 4 * n * n / std::numbers::pi * camera.exposure_scale() / pixel_area_m2;
    front_radius_mm = 0.5 * lens->prescription().surfaces.front().aperture_diameter_mm;
  }

  // The crop's pixel coordinates of a lens-space sensor point (the image is inverted there).
  Point2d pixel_of(Point2d sensor_mm) const {
    return {(-sensor_mm.x / sensor_width_mm + 0.5) * width_px - crop.min.x,
            (0.5 + sensor_mm.y / sensor_height_mm) * height_px - crop.min.y};
  }
};

// A source in lens space: a point (mm) or a direction of travel.
struct LensSource {
  bool at_infinity = false;
  Point3d position;
  Vector3d direction;
  Rgb intensity;  // W/sr, or W/m² at infinity
};

std::optional<LensSource> to_lens_space(const FlareSource& s, const FlareOptics& o) {
  LensSource out;
  out.at_infinity = s.at_infinity;
  out.intensity = s.intensity;
  const double film = o.focused->film_distance_mm();
  if (s.at_infinity) {
    Vector3d v = o.camera_from_world(s.direction);
    out.direction = Vector3d(v.x, v.y, -v.z) / length(v);
    if (!(out.direction.z < 0)) return std::nullopt;  // not towards the lens
  } else {
    Point3d p = o.camera_from_world(s.position);
    out.position = Point3d(p.x * kMillimetresPerMetre, p.y * kMillimetresPerMetre,
                           -p.z * kMillimetresPerMetre - film);
    if (!(out.position.z > o.lens->front_z_mm())) return std::nullopt;  // behind the front
  }
  return out;
}

// The square of the front vertex plane whose rays can reach the lens: the front element's
// radius, grown for oblique light (which crosses the plane away from where it meets the
// curved surface).
struct Square {
  double centre_x = 0, centre_y = 0, half = 0;
};
Square search_square(const LensSource& s, const FlareOptics& o) {
  const Point3d front(0, 0, o.lens->front_z_mm());
  Vector3d d = s.at_infinity ? s.direction : (front - s.position) / length(front - s.position);
  const double tan_theta = std::hypot(d.x, d.y) / std::max(1e-6, -d.z);
  return {0, 0, o.front_radius_mm * (1 + std::min(tan_theta, 3.0))};
}

// The ray from the source through point (x, y) of the front vertex plane, and the power per unit
// area of that plane it stands for (W/mm²).
struct SourceRay {
  LensRay ray;
  double density = 0;
};
std::optional<SourceRay> source_ray(const LensSource& s, const FlareOptics& o, double x, double y) {
  const Point3d q(x, y, o.lens->front_z_mm());
  // Started well in front of the plane, where no surface reaches (fisheye fronts bulge far).
  const double back_off = 4 * o.front_radius_mm + 1;
  if (s.at_infinity) {
    const double cos_theta = -s.direction.z;
    return SourceRay{{q - s.direction * back_off, s.direction},
                     kSquareMetresPerSquareMillimetre * cos_theta};
  }
  const Vector3d to = q - s.position;
  const double r = length(to);
  const Vector3d d = to / r;
  if (!(d.z < 0)) return std::nullopt;
  const Point3d origin = r > back_off ? q - d * back_off : s.position;
  return SourceRay{{origin, d}, -d.z / (r * r)};
}

struct TracedVertex {
  Point2d pixel;
  double gauge = std::numeric_limits<double>::infinity();
  double power = 0;  // W per mm² of the front plane, throughput included (one wavelength)
};

TracedVertex trace_vertex(const LensSource& s, const FlareOptics& o,
                          const std::vector<SurfaceVisit>& path, double x, double y,
                          double wavelength_nm) {
  TracedVertex v;
  v.pixel.x = std::numeric_limits<double>::quiet_NaN();
  std::optional<SourceRay> sr = source_ray(s, o, x, y);
  if (!sr) return v;
  thread_local std::vector<InterfaceHit> hits;
  std::optional<SensorHit> hit = trace_to_sensor(
      *o.lens, path, sr->ray, o.focused->film_distance_mm(), wavelength_nm, o.stop, hits);
  if (!hit) return v;
  v.pixel = o.pixel_of(hit->sensor_mm);
  v.gauge = hit->aperture_gauge;
  v.power = sr->density * path_throughput(hits, o.coating, wavelength_nm);
  return v;
}

// A path's colour within each band relative to its traced wavelength: Σ over the band's steps of
// the channel weight × the axial throughput there / the axial throughput at the band's centre.
using BandColours = std::array<std::array<double, 3>, kBands>;
BandColours band_colours(const FlareOptics& o, const std::vector<SurfaceVisit>& path) {
  auto axial = [&](double nm) {
    std::vector<InterfaceHit> hits;
    for (const SurfaceVisit& visit : path)
      hits.push_back({visit.surface, visit.reflect, 1, o.lens->index_before(visit.surface, nm),
                      o.lens->index_after(visit.surface, nm)});
    return path_throughput(hits, o.coating, nm);
  };
  BandColours colours{};
  const ChannelWeights& w = channel_weights();
  for (int b = 0; b < kBands; ++b) {
    const double centre = axial(band_centre_nm(b));
    for (int s = 0; s < kStepsPerBand; ++s) {
      const double relative = centre > 0 ? axial(step_nm(b, s)) / centre : 0;
      for (int c = 0; c < 3; ++c)
        colours[size_t(b)][size_t(c)] += w[size_t(b)][size_t(s)][size_t(c)] * relative;
    }
  }
  return colours;
}

// One path's grids (one per band) for one source; none when no ray reaches the sensor or the
// image would stay below the threshold (`skip_faint`).
struct PathImage {
  std::vector<RayGrid> grids;
  double rays = 0;
};
PathImage trace_path(const LensSource& s, const FlareOptics& o,
                     const std::vector<SurfaceVisit>& path, const FlareSettings& settings,
                     bool skip_faint) {
  PathImage out;
  const Square square = search_square(s, o);
  // 1. The coarse grid at the middle band: which part of the front plane passes, its power.
  const int n = settings.search_cells;
  const double cell = 2 * square.half / n;
  double x_min = 1e300, x_max = -1e300, y_min = 1e300, y_max = -1e300, power = 0;
  double px_min = 1e300, px_max = -1e300, py_min = 1e300, py_max = -1e300;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const double x = square.centre_x - square.half + i * cell;
      const double y = square.centre_y - square.half + j * cell;
      TracedVertex v = trace_vertex(s, o, path, x, y, band_centre_nm(1));
      out.rays += 1;
      if (!(v.gauge <= 1) || !std::isfinite(v.pixel.x)) continue;
      x_min = std::min(x_min, x), x_max = std::max(x_max, x);
      y_min = std::min(y_min, y), y_max = std::max(y_max, y);
      px_min = std::min(px_min, v.pixel.x), px_max = std::max(px_max, v.pixel.x);
      py_min = std::min(py_min, v.pixel.y), py_max = std::max(py_max, v.pixel.y);
      power += v.power * cell * cell;
    }
  if (x_min > x_max) return out;
  if (skip_faint) {
    const double brightest = std::max({s.intensity.r, s.intensity.g, s.intensity.b});
    const double footprint = std::max(1.0, (px_max - px_min + 1) * (py_max - py_min + 1));
    if (power * brightest * o.film_per_watt / footprint < settings.min_film_value) return out;
  }
  // 2. The fine grid over that part, a coarse cell wider on every side (the coarse grid's
  // passing points are inside the opening; its edge lies up to a cell beyond them).
  x_min = std::max(square.centre_x - square.half, x_min - cell);
  x_max = std::min(square.centre_x + square.half, x_max + cell);
  y_min = std::max(square.centre_y - square.half, y_min - cell);
  y_max = std::min(square.centre_y + square.half, y_max + cell);
  const int m = settings.grid_cells;
  const double dx = (x_max - x_min) / m, dy = (y_max - y_min) / m;
  const BandColours colours = band_colours(o, path);
  const double scale[3] = {s.intensity.r * o.film_per_watt, s.intensity.g * o.film_per_watt,
                           s.intensity.b * o.film_per_watt};
  for (int b = 0; b < kBands; ++b) {
    RayGrid grid;
    grid.cells = m;
    grid.cell_area = dx * dy;
    const size_t vertices = size_t(m + 1) * size_t(m + 1);
    grid.position_px.resize(vertices), grid.gauge.resize(vertices);
    grid.power_density.resize(vertices);
    for (int j = 0; j <= m; ++j)
      for (int i = 0; i <= m; ++i) {
        const size_t k = size_t(j) * size_t(m + 1) + size_t(i);
        TracedVertex v =
            trace_vertex(s, o, path, x_min + i * dx, y_min + j * dy, band_centre_nm(b));
        grid.position_px[k] = v.pixel;
        grid.gauge[k] = v.gauge;
        for (int c = 0; c < 3; ++c)
          grid.power_density[k][size_t(c)] =
              float(v.power * colours[size_t(b)][size_t(c)] * scale[c]);
      }
    out.rays += double(vertices);
    out.grids.push_back(std::move(grid));
  }
  return out;
}

void splat_all(const std::vector<PathImage>& images, Image& image) {
  const int tasks = (image.height + kRowsPerTask - 1) / kRowsPerTask;
  tbb::parallel_for(0, tasks, [&](int t) {
    for (const PathImage& p : images)
      for (const RayGrid& grid : p.grids)
        splat_ray_grid(grid, image, t * kRowsPerTask, (t + 1) * kRowsPerTask);
  });
}

}  // namespace

void validate(const FlareSettings& s) {
  if (s.grid_cells < 4 || s.grid_cells > 1024)
    throw Error("flare.grid_cells", "must be in [4, 1024]; got " + std::to_string(s.grid_cells));
  if (s.search_cells < 4 || s.search_cells > 1024)
    throw Error("flare.search_cells",
                "must be in [4, 1024]; got " + std::to_string(s.search_cells));
  if (!(s.min_film_value >= 0) || !std::isfinite(s.min_film_value))
    throw Error("flare.min_film_value",
                "must be 0 or positive; got " + number_text(s.min_film_value));
}

std::vector<FlareSource> flare_sources(const Scene& scene, const Camera& camera) {
  const double time = camera.shutter.time_at(0.5);
  const Point3d eye = camera.world_from_camera.at(time)(Point3d(0, 0, 0));
  std::vector<FlareSource> sources;
  auto is_dark = [](Rgb c) { return !(std::max({c.r, c.g, c.b}) > 0); };
  for (const Light& light : scene.lights) {
    FlareSource s;
    s.name = light.name;
    if (auto* p = std::get_if<PointLight>(&light.model)) {
      s.position = Point3d(p->position.x, p->position.y, p->position.z);
      s.intensity = p->intensity;
    } else if (auto* spot = std::get_if<SpotLight>(&light.model)) {
      const PunctualLight model =
          PunctualLight::spot(spot->position, spot->direction, spot->intensity,
                              spot->inner_cone_radians, spot->outer_cone_radians);
      s.position = Point3d(spot->position.x, spot->position.y, spot->position.z);
      const Vector3d towards = eye - s.position;
      const double distance = length(towards);
      if (!(distance > 0)) continue;
      const Vector3d w = towards / distance;
      s.intensity =
          spot->intensity * model.spot_falloff(Vector3f(float(w.x), float(w.y), float(w.z)));
    } else if (auto* d = std::get_if<DirectionalLight>(&light.model)) {
      s.at_infinity = true;
      s.direction = Vector3d(d->direction.x, d->direction.y, d->direction.z);
      s.direction = s.direction / length(s.direction);
      s.intensity = d->irradiance;
    }
    if (!is_dark(s.intensity)) sources.push_back(s);
  }
  // Emissive objects: Σ L·A·cos θ over the faces turned to the camera (lights emit from their
  // front faces), at the centroid of that emission. θ is measured from one direction, from the
  // object's middle to the camera: the intensity of a small source seen from afar (per-face
  // directions would shrink a sphere's by 4/3 of its radius over the distance).
  for (const Instance& instance : scene.instances) {
    const Material& material = scene.materials[scene.material_of(instance)];
    if (is_dark(material.emission)) continue;
    const Mesh& mesh = scene.meshes[instance.mesh];
    const Transform& world_from_object = instance.world_from_object;
    std::vector<Point3d> world(mesh.positions.size());
    Vector3d middle(0, 0, 0);
    for (size_t v = 0; v < world.size(); ++v) {
      const Point3f p = world_from_object(mesh.positions[v]);
      world[v] = Point3d(p.x, p.y, p.z);
      middle = middle + Vector3d(p.x, p.y, p.z) / double(world.size());
    }
    const Vector3d towards = eye - Point3d(middle.x, middle.y, middle.z);
    if (world.empty() || !(length(towards) > 0)) continue;
    const Vector3d w = towards / length(towards);
    double r = 0, g = 0, b = 0, weight = 0;
    Vector3d centroid(0, 0, 0);
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
      const Point3d p[3] = {world[mesh.indices[t]], world[mesh.indices[t + 1]],
                            world[mesh.indices[t + 2]]};
      const Vector3d normal_area2 = cross(p[1] - p[0], p[2] - p[0]);  // |·| = 2 × area
      const Point3d centre((p[0].x + p[1].x + p[2].x) / 3, (p[0].y + p[1].y + p[2].y) / 3,
                           (p[0].z + p[1].z + p[2].z) / 3);
      // A·cos θ = ½ |n2| · (n̂ · ŵ) = ½ n2 · ŵ.
      const double projected = 0.5 * dot(normal_area2, w);
      if (!(projected > 0)) continue;
      r += material.emission.r * projected, g += material.emission.g * projected;
      b += material.emission.b * projected;
      weight += projected;
      centroid = centroid + Vector3d(centre.x, centre.y, centre.z) * projected;
    }
    if (!(weight > 0)) continue;
    FlareSource s;
    s.name = instance.name;
    s.position = Point3d(centroid.x / weight, centroid.y / weight, centroid.z / weight);
    s.intensity = Rgb(float(r), float(g), float(b));
    sources.push_back(s);
  }
  return sources;
}

Image lens_flare_image(const std::vector<FlareSource>& sources, const Camera& camera,
                       const FlareSettings& settings, FlareStats* stats) {
  validate(settings);
  const auto start = std::chrono::steady_clock::now();
  const FlareOptics optics(camera);
  const Bounds2i crop = camera.film.crop_pixels();
  Image image(crop.width(), crop.height(), 3);
  image.channel_names = {"R", "G", "B"};
  // Cost first: the ghosts and their paths grow with the square of the lens's surfaces.
  const size_t surfaces = optics.lens->prescription().surfaces.size();
  if (surfaces > size_t(kMaxFlareLensSurfaces))
    throw Error("flare", "the lens has " + std::to_string(surfaces) + " surfaces (up to " +
                             std::to_string(surfaces * (surfaces - 1) / 2) +
                             " ghosts); ghost flares are traced for lenses of at most " +
                             std::to_string(kMaxFlareLensSurfaces) + " surfaces");
  const std::vector<Ghost> ghosts = lens_ghosts(*optics.lens);
  const long long work = (long long)ghosts.size() * (long long)sources.size() * (long long)surfaces;
  if (work > kMaxFlareWork)
    throw Error("flare", std::to_string(ghosts.size()) + " ghosts × " +
                             std::to_string(sources.size()) + " bright lights × " +
                             std::to_string(surfaces) + " lens surfaces = " + std::to_string(work) +
                             " ghost-surface traces; at most " + std::to_string(kMaxFlareWork) +
                             " are traced (fewer lights, or a simpler lens)");
  std::vector<std::vector<SurfaceVisit>> paths;
  for (const Ghost& g : ghosts) paths.push_back(ghost_path(*optics.lens, g));
  FlareStats local;
  auto cancelled = [&] { return settings.cancel && settings.cancel->load(); };
  for (const FlareSource& source : sources) {
    if (cancelled()) {
      local.cancelled = true;
      break;
    }
    std::optional<LensSource> s = to_lens_space(source, optics);
    if (!s) continue;
    // Every ghost traced in parallel, then splatted row band by row band in ghost order. A
    // cancel skips the ghosts not yet started and the source is left out whole.
    std::vector<PathImage> images(paths.size());
    tbb::parallel_for(size_t(0), paths.size(), [&](size_t g) {
      if (!cancelled()) images[g] = trace_path(*s, optics, paths[g], settings, /*skip_faint=*/true);
    });
    if (cancelled()) {
      local.cancelled = true;
      break;
    }
    ++local.sources;
    for (const PathImage& p : images) {
      local.rays += p.rays;
      ++(p.grids.empty() ? local.ghosts_skipped : local.ghosts_traced);
    }
    splat_all(images, image);
  }
  local.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (stats) *stats = local;
  return image;
}

Image lens_flare_image(const Scene& scene, const Camera& camera, const FlareSettings& settings,
                       FlareStats* stats) {
  return lens_flare_image(flare_sources(scene, camera), camera, settings, stats);
}

void add_lens_flare(Image& frame, const Image& flare) {
  if (frame.width != flare.width || frame.height != flare.height || frame.channels < 3 ||
      flare.channels != 3)
    throw Error("flare", "the flare image (" + std::to_string(flare.width) + "x" +
                             std::to_string(flare.height) + ") does not match the frame (" +
                             std::to_string(frame.width) + "x" + std::to_string(frame.height) +
                             ")");
  for (int y = 0; y < frame.height; ++y)
    for (int x = 0; x < frame.width; ++x)
      for (int c = 0; c < 3; ++c) frame.at(x, y, c) += flare.at(x, y, c);
}

Image lens_path_image(const FlareSource& source, const Camera& camera,
                      const std::vector<SurfaceVisit>& path, const FlareSettings& settings) {
  validate(settings);
  const FlareOptics optics(camera);
  const Bounds2i crop = camera.film.crop_pixels();
  Image image(crop.width(), crop.height(), 3);
  std::optional<LensSource> s = to_lens_space(source, optics);
  if (!s) return image;
  splat_all({trace_path(*s, optics, path, settings, /*skip_faint=*/false)}, image);
  return image;
}

}  // namespace obscura
