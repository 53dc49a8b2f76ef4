#include "obscura/film/ray_grid_splat.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace obscura {

namespace {

struct Corner {
  Point2d p;
  double gauge;
};

// Twice the signed area of (u, v, p), computed the same way from both triangles that share the
// edge u–v (endpoints in a fixed order, the sign flipped after), so that the two see exactly
// opposite values and a pixel centre on the edge goes to exactly one of them.
double edge_function(Point2d u, Point2d v, Point2d p) {
  const bool swapped = v.x < u.x || (v.x == u.x && v.y < u.y);
  if (swapped) std::swap(u, v);
  const double e = (v.x - u.x) * (p.y - u.y) - (v.y - u.y) * (p.x - u.x);
  return swapped ? -e : e;
}

// Of the two triangles on either side of an edge, the one that owns centres lying on it: a fixed
// half of the edge directions (the other triangle traverses the edge the opposite way).
bool owns_edge(Point2d u, Point2d v) {
  const double dx = v.x - u.x, dy = v.y - u.y;
  return dy > 0 || (dy == 0 && dx > 0);
}

bool inside(double e, Point2d u, Point2d v) {
  return e > 0 || (e == 0 && owns_edge(u, v));
}

void add(Image& image, int x, int y, const std::array<double, 3>& value, double scale) {
  for (int c = 0; c < 3; ++c) image.at(x, y, c) += float(value[size_t(c)] * scale);
}

// Power at point p spread bilinearly over the four nearest pixel centres.
void splat_point(Point2d p, const std::array<double, 3>& power, Image& image, int row_begin,
                 int row_end) {
  const double u = p.x - 0.5, v = p.y - 0.5;
  const int x0 = int(std::floor(u)), y0 = int(std::floor(v));
  const double fx = u - x0, fy = v - y0;
  for (int dy = 0; dy < 2; ++dy) {
    const int y = y0 + dy;
    if (y < row_begin || y >= row_end) continue;
    for (int dx = 0; dx < 2; ++dx) {
      const int x = x0 + dx;
      if (x < 0 || x >= image.width) continue;
      add(image, x, y, power, (dx ? fx : 1 - fx) * (dy ? fy : 1 - fy));
    }
  }
}

void splat_triangle(Corner a, Corner b, Corner c, const std::array<double, 3>& power, Image& image,
                    int row_begin, int row_end) {
  double area2 = edge_function(a.p, b.p, c.p);
  if (!(area2 != 0) || !std::isfinite(area2)) return;  // degenerate
  if (area2 < 0) std::swap(b, c), area2 = -area2;
  const double x_min = std::min({a.p.x, b.p.x, c.p.x}), x_max = std::max({a.p.x, b.p.x, c.p.x});
  const double y_min = std::min({a.p.y, b.p.y, c.p.y}), y_max = std::max({a.p.y, b.p.y, c.p.y});
  // Smaller than a pixel: all of its power at its centroid, if the centroid passed.
  if (x_max - x_min < 1 && y_max - y_min < 1) {
    if ((a.gauge + b.gauge + c.gauge) / 3 > 1) return;
    splat_point({(a.p.x + b.p.x + c.p.x) / 3, (a.p.y + b.p.y + c.p.y) / 3}, power, image, row_begin,
                row_end);
    return;
  }
  // The pixel centres (x + ½, y + ½) inside, where the interpolated gauge passes.
  const int y_first = std::max(row_begin, int(std::ceil(y_min - 0.5)));
  const int y_last = std::min(row_end - 1, int(std::floor(y_max - 0.5)));
  const int x_first = std::max(0, int(std::ceil(x_min - 0.5)));
  const int x_last = std::min(image.width - 1, int(std::floor(x_max - 0.5)));
  const double per_pixel = 2 / area2;  // power per unit area (pixels²)
  const double gauge_max = std::max({a.gauge, b.gauge, c.gauge});
  for (int y = y_first; y <= y_last; ++y)
    for (int x = x_first; x <= x_last; ++x) {
      const Point2d p(x + 0.5, y + 0.5);
      const double wa = edge_function(b.p, c.p, p), wb = edge_function(c.p, a.p, p),
                   wc = edge_function(a.p, b.p, p);
      if (!inside(wa, b.p, c.p) || !inside(wb, c.p, a.p) || !inside(wc, a.p, b.p)) continue;
      if (gauge_max > 1 && (wa * a.gauge + wb * b.gauge + wc * c.gauge) > area2) continue;
      add(image, x, y, power, per_pixel);
    }
}

}  // namespace

void splat_ray_grid(const RayGrid& grid, Image& image, int row_begin, int row_end) {
  row_begin = std::max(row_begin, 0), row_end = std::min(row_end, image.height);
  if (row_begin >= row_end) return;
  const int side = grid.vertices_per_side();
  auto corner = [&](int i, int j) {
    const size_t k = size_t(j) * side + i;
    return Corner{grid.position_px[k], grid.gauge[k]};
  };
  auto usable = [&](int i, int j) {
    const size_t k = size_t(j) * side + i;
    return std::isfinite(grid.position_px[k].x) && grid.gauge[k] < 1e30;
  };
  // A triangle's power: its starting area times the mean power density of its corners.
  auto triangle_power = [&](int i0, int j0, int i1, int j1, int i2, int j2) {
    std::array<double, 3> power{};
    for (auto [i, j] : {std::pair{i0, j0}, std::pair{i1, j1}, std::pair{i2, j2}}) {
      const auto& d = grid.power_density[size_t(j) * side + i];
      for (int c = 0; c < 3; ++c) power[size_t(c)] += d[size_t(c)];
    }
    for (double& p : power) p *= grid.cell_area / 2 / 3;
    return power;
  };
  for (int j = 0; j < grid.cells; ++j)
    for (int i = 0; i < grid.cells; ++i) {
      const bool v00 = usable(i, j), v10 = usable(i + 1, j), v01 = usable(i, j + 1),
                 v11 = usable(i + 1, j + 1);
      // Both triangles share the diagonal 00–11.
      if (v00 && v11 && v10) {
        // Every corner outside the openings: nothing of it can pass (the gauge is interpolated).
        if (!(corner(i, j).gauge > 1 && corner(i + 1, j).gauge > 1 &&
              corner(i + 1, j + 1).gauge > 1))
          splat_triangle(corner(i, j), corner(i + 1, j), corner(i + 1, j + 1),
                         triangle_power(i, j, i + 1, j, i + 1, j + 1), image, row_begin, row_end);
      }
      if (v00 && v11 && v01) {
        if (!(corner(i, j).gauge > 1 && corner(i, j + 1).gauge > 1 &&
              corner(i + 1, j + 1).gauge > 1))
          splat_triangle(corner(i, j), corner(i + 1, j + 1), corner(i, j + 1),
                         triangle_power(i, j, i + 1, j + 1, i, j + 1), image, row_begin, row_end);
      }
    }
}

}  // namespace obscura
