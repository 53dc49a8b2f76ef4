// The camera a file without one gets: it sees every model, flat ones included.
#include "obscura/io/camera_mapping.h"

#include <gtest/gtest.h>

#include <cmath>

namespace obscura {
namespace {

// Shoelace area of the corners' projections, as a fraction of the film (all corners in view).
double covered_fraction(const Camera& camera, const std::vector<Point3d>& corners) {
  std::vector<Point2d> p;
  for (Point3d c : corners) {
    std::optional<FilmProjection> f = camera.project(c);
    if (!f) return -1;
    if (f->film_point.x < 0 || f->film_point.x > camera.film.width_px || f->film_point.y < 0 ||
        f->film_point.y > camera.film.height_px)
      return -1;
    p.push_back(f->film_point);
  }
  double area = 0;
  for (size_t i = 0; i < p.size(); ++i) {
    const Point2d &a = p[i], &b = p[(i + 1) % p.size()];
    area += a.x * b.y - b.x * a.y;
  }
  return std::abs(area) / 2 / (double(camera.film.width_px) * camera.film.height_px);
}

TEST(FramingCamera, SeesAFlatModelInEveryPlane) {
  // A 2 × 2 square lying in each coordinate plane (TwoSidedPlane lies in XZ: from straight in
  // front it is a line). The three-quarter view sees each as a quadrilateral covering a good part
  // of the frame, never edge-on.
  const std::vector<std::vector<Point3d>> squares = {
      {{-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1}},   // XZ (floor)
      {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}},   // XY (facing front)
      {{0, -1, -1}, {0, 1, -1}, {0, 1, 1}, {0, -1, 1}}};  // YZ (facing the side)
  for (const auto& square : squares) {
    Bounds3f bounds;
    for (Point3d c : square) bounds = unite(bounds, Point3f(float(c.x), float(c.y), float(c.z)));
    Camera camera = framing_camera(bounds);
    camera.film.width_px = camera.film.height_px = 100;
    double fraction = covered_fraction(camera, square);
    EXPECT_GT(fraction, 0.08) << "square " << (&square - &squares[0]);
  }
}

TEST(FramingCamera, AFullBoxStaysInsideTheFrame) {
  Bounds3f bounds(Point3f(-1, -2, -3), Point3f(4, 5, 6));
  Camera camera = framing_camera(bounds);
  camera.film.width_px = camera.film.height_px = 64;
  for (int i = 0; i < 8; ++i) {
    Point3d corner(i & 1 ? 4 : -1, i & 2 ? 5 : -2, i & 4 ? 6 : -3);
    std::optional<FilmProjection> f = camera.project(corner);
    ASSERT_TRUE(f);
    EXPECT_GE(f->film_point.x, 0);
    EXPECT_LE(f->film_point.x, 64);
    EXPECT_GE(f->film_point.y, 0);
    EXPECT_LE(f->film_point.y, 64);
  }
}

}  // namespace
}  // namespace obscura
