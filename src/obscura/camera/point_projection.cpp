#include "obscura/camera/point_projection.h"

#include <tbb/parallel_for.h>

#include <atomic>
#include <cmath>
#include <limits>
#include <variant>

namespace obscura {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// Points per task: large enough that scheduling is noise, small enough to share 10^5 points.
constexpr size_t kGrain = 8192;

template <typename Body>
void for_chunks(size_t n, const Body& body) {
  tbb::parallel_for(tbb::blocked_range<size_t>(0, n, kGrain),
                    [&](const tbb::blocked_range<size_t>& r) { body(r.begin(), r.end()); });
}

// A perspective or orthographic camera at one time: Camera::project's and unproject's planar
// branches with the pose and the screen window computed once. The expressions are theirs
// (camera.cpp: raster_from_window, window_from_raster, on_film), in the same order, so the
// results are the same doubles.
struct PlanarCamera {
  Transform world_from_camera, camera_from_world;
  ScreenWindow window;
  double window_width, window_height;
  double width_px, height_px;
  double near_m, far_m;
  bool perspective;
  // The pose's last row is (0, 0, 0, 1), so Transform's homogeneous w is exactly 1 for every
  // finite point and its divide never happens: the loop may skip it and run without branches.
  bool affine;

  PlanarCamera(const Camera& c, double time_s)
      : world_from_camera(c.world_from_camera.at(time_s)),
        camera_from_world(inverse(world_from_camera)),
        window(c.screen_window()),
        window_width(window.x_max - window.x_min),
        window_height(window.y_max - window.y_min),
        width_px(c.film.width_px),
        height_px(c.film.height_px),
        near_m(c.near_m),
        far_m(c.far_m),
        perspective(std::holds_alternative<Perspective>(c.projection)) {
    const auto& m = camera_from_world.matrix().m;
    affine = m[3][0] == 0 && m[3][1] == 0 && m[3][2] == 0 && m[3][3] == 1;
  }

  bool on_film(double x, double y) const {
    constexpr double kSlackPx = 1e-9;  // as camera.cpp's on_film
    return x >= -kSlackPx && x <= width_px + kSlackPx && y >= -kSlackPx &&
           y <= height_px + kSlackPx;
  }

  // Returns whether every coordinate was finite.
  template <bool kPerspective, typename T>
  bool project(const T* world, size_t begin, size_t end, double* film, double* depth) const {
    bool finite = true;
    for (size_t i = begin; i < end; ++i) {
      const Point3d p(world[3 * i], world[3 * i + 1], world[3 * i + 2]);
      const bool point_finite = std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
      finite = finite && point_finite;
      const Point3d q = camera_from_world(p);
      const double d = -q.z;
      double x = kNaN, y = kNaN, z = kNaN;
      if (point_finite && d >= near_m && d <= far_m) {
        const double wx = kPerspective ? q.x / d : q.x, wy = kPerspective ? q.y / d : q.y;
        const double rx = (wx - window.x_min) / window_width * width_px;
        const double ry = (window.y_max - wy) / window_height * height_px;
        if (on_film(rx, ry)) x = rx, y = ry, z = d;
      }
      film[2 * i] = x, film[2 * i + 1] = y, depth[i] = z;
    }
    return finite;
  }

  // project() for an affine pose with every test evaluated and the results selected, so that
  // the compiler can vectorize it. Transform::operator()'s sums in its order (w = 1 needs no
  // divide); a point that fails a test computes garbage that is thrown away.
  template <bool kPerspective, typename T>
  bool project_affine(const T* world, size_t begin, size_t end, double* film, double* depth) const {
    const auto& m = camera_from_world.matrix().m;
    constexpr double kSlackPx = 1e-9;  // as camera.cpp's on_film
    bool finite = true;
    for (size_t i = begin; i < end; ++i) {
      const double x = world[3 * i], y = world[3 * i + 1], z = world[3 * i + 2];
      const bool point_finite = std::isfinite(x) & std::isfinite(y) & std::isfinite(z);
      finite &= point_finite;
      const double qx = m[0][0] * x + m[0][1] * y + m[0][2] * z + m[0][3];
      const double qy = m[1][0] * x + m[1][1] * y + m[1][2] * z + m[1][3];
      const double qz = m[2][0] * x + m[2][1] * y + m[2][2] * z + m[2][3];
      const double d = -qz;
      const double wx = kPerspective ? qx / d : qx, wy = kPerspective ? qy / d : qy;
      const double rx = (wx - window.x_min) / window_width * width_px;
      const double ry = (window.y_max - wy) / window_height * height_px;
      const bool seen = point_finite & (d >= near_m) & (d <= far_m) & (rx >= -kSlackPx) &
                        (rx <= width_px + kSlackPx) & (ry >= -kSlackPx) &
                        (ry <= height_px + kSlackPx);
      film[2 * i] = seen ? rx : kNaN;
      film[2 * i + 1] = seen ? ry : kNaN;
      depth[i] = seen ? d : kNaN;
    }
    return finite;
  }

  template <typename T>
  void unproject(const T* film, const T* depth, size_t begin, size_t end, double* world) const {
    for (size_t i = begin; i < end; ++i) {
      const double d = depth[i];
      const double wx = window.x_min + double(film[2 * i]) / width_px * window_width;
      const double wy = window.y_max - double(film[2 * i + 1]) / height_px * window_height;
      const Point3d q = perspective ? Point3d(wx * d, wy * d, -d) : Point3d(wx, wy, -d);
      const Point3d w = world_from_camera(q);
      world[3 * i] = w.x, world[3 * i + 1] = w.y, world[3 * i + 2] = w.z;
    }
  }
};

}  // namespace

template <typename T>
bool project_points(const Camera& camera, const T* world, size_t n, double time_s, double* film,
                    double* depth) {
  std::atomic<bool> finite = true;
  if (camera.has_projection_matrix()) {
    const PlanarCamera planar(camera, time_s);
    for_chunks(n, [&](size_t begin, size_t end) {
      bool chunk_finite;
      if (planar.affine)
        chunk_finite = planar.perspective
                           ? planar.project_affine<true>(world, begin, end, film, depth)
                           : planar.project_affine<false>(world, begin, end, film, depth);
      else
        chunk_finite = planar.perspective ? planar.project<true>(world, begin, end, film, depth)
                                          : planar.project<false>(world, begin, end, film, depth);
      if (!chunk_finite) finite = false;
    });
    return finite;
  }
  // Spherical and calibrated cameras: their per-point trigonometry or lens solve outweighs the
  // pose and the dispatch, so they go through Camera::project itself, prepared once.
  const PreparedCamera prepared = camera.prepare();
  for_chunks(n, [&](size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i) {
      const Point3d p(world[3 * i], world[3 * i + 1], world[3 * i + 2]);
      std::optional<FilmProjection> fp;
      if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z))
        fp = prepared.project(p, time_s);
      else
        finite = false;
      film[2 * i] = fp ? fp->film_point.x : kNaN;
      film[2 * i + 1] = fp ? fp->film_point.y : kNaN;
      depth[i] = fp ? fp->depth_m : kNaN;
    }
  });
  return finite;
}

template <typename T>
void unproject_points(const Camera& camera, const T* film, const T* depth, size_t n, double time_s,
                      double* world) {
  if (camera.has_projection_matrix()) {
    const PlanarCamera planar(camera, time_s);
    for_chunks(n,
               [&](size_t begin, size_t end) { planar.unproject(film, depth, begin, end, world); });
    return;
  }
  const PreparedCamera prepared = camera.prepare();
  for_chunks(n, [&](size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i) {
      std::optional<Point3d> w =
          prepared.unproject({film[2 * i], film[2 * i + 1]}, depth[i], time_s);
      for (int k = 0; k < 3; ++k) world[3 * i + size_t(k)] = w ? (*w)[k] : kNaN;
    }
  });
}

template bool project_points(const Camera&, const float*, size_t, double, double*, double*);
template bool project_points(const Camera&, const double*, size_t, double, double*, double*);
template void unproject_points(const Camera&, const float*, const float*, size_t, double, double*);
template void unproject_points(const Camera&, const double*, const double*, size_t, double,
                               double*);

}  // namespace obscura
