#include "obscura/camera/lens_distortion.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "obscura/math/error.h"
#include "obscura/math/number_text.h"

namespace obscura {

namespace {

constexpr double kPi = std::numbers::pi;
// The pinhole sees rays up to (not including) 90°; tan(θ) must stay finite.
constexpr double kPinholeReach = kPi / 2 - 1e-6;
// Stereographic's radius 2 tan(θ/2) is infinite at 180°.
constexpr double kStereographicReach = kPi - 1e-6;
constexpr int kScanSteps = 1024;

// The rational radial factor of OpenCV's pinhole model, and its derivative in r².
struct Radial {
  double factor, derivative, denominator;
};
Radial radial(const PinholeDistortion& d, double r2) {
  double n = 1 + r2 * (d.k1 + r2 * (d.k2 + r2 * d.k3));
  double dn = d.k1 + r2 * (2 * d.k2 + 3 * r2 * d.k3);
  double m = 1 + r2 * (d.k4 + r2 * (d.k5 + r2 * d.k6));
  double dm = d.k4 + r2 * (2 * d.k5 + 3 * r2 * d.k6);
  return {n / m, (dn * m - n * dm) / (m * m), m};
}

// OpenCV's tilted-sensor matrix: the sensor turned by τx about X, then τy about Y, and the
// projection back onto the plane z = 1 along the turned axis.
struct Tilt {
  double m[3][3];
};
Tilt tilt_matrix(double tau_x, double tau_y) {
  double cx = std::cos(tau_x), sx = std::sin(tau_x), cy = std::cos(tau_y), sy = std::sin(tau_y);
  // R = Ry · Rx with Rx = [1 0 0; 0 cx sx; 0 −sx cx], Ry = [cy 0 −sy; 0 1 0; sy 0 cy].
  double r[3][3] = {{cy, sy * sx, -sy * cx}, {0, cx, sx}, {sy, -cy * sx, cy * cx}};
  // P = [r22 0 −r02; 0 r22 −r12; 0 0 1]; tilt = P · R.
  double p[3][3] = {{r[2][2], 0, -r[0][2]}, {0, r[2][2], -r[1][2]}, {0, 0, 1}};
  Tilt t{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) t.m[i][j] += p[i][k] * r[k][j];
  return t;
}
Point2d apply(const std::array<double, 9>& m, Point2d p) {
  double x = m[0] * p.x + m[1] * p.y + m[2];
  double y = m[3] * p.x + m[4] * p.y + m[5];
  double w = m[6] * p.x + m[7] * p.y + m[8];
  return {x / w, y / w};
}
Tilt inverted(const Tilt& t) {
  const auto& m = t.m;
  double c00 = m[1][1] * m[2][2] - m[1][2] * m[2][1], c01 = m[0][2] * m[2][1] - m[0][1] * m[2][2],
         c02 = m[0][1] * m[1][2] - m[0][2] * m[1][1];
  double c10 = m[1][2] * m[2][0] - m[1][0] * m[2][2], c11 = m[0][0] * m[2][2] - m[0][2] * m[2][0],
         c12 = m[0][2] * m[1][0] - m[0][0] * m[1][2];
  double c20 = m[1][0] * m[2][1] - m[1][1] * m[2][0], c21 = m[0][1] * m[2][0] - m[0][0] * m[2][1],
         c22 = m[0][0] * m[1][1] - m[0][1] * m[1][0];
  double det = m[0][0] * c00 + m[0][1] * c10 + m[0][2] * c20;
  return {{{c00 / det, c01 / det, c02 / det},
           {c10 / det, c11 / det, c12 / det},
           {c20 / det, c21 / det, c22 / det}}};
}
bool has_tilt(const PinholeDistortion& d) {
  return d.tau_x != 0 || d.tau_y != 0;
}

// The pinhole's distortion of an undistorted point (x, y) = (X/Z, Y/Z), before the tilt, and its
// Jacobian.
struct Distorted {
  Point2d p;
  double dxdx, dxdy, dydx, dydy;
};
Distorted distort(const PinholeDistortion& d, Point2d u) {
  double x = u.x, y = u.y, r2 = x * x + y * y;
  Radial rad = radial(d, r2);
  double R = rad.factor, dR = rad.derivative;
  Distorted out;
  out.p.x = x * R + 2 * d.p1 * x * y + d.p2 * (r2 + 2 * x * x) + r2 * (d.s1 + d.s2 * r2);
  out.p.y = y * R + d.p1 * (r2 + 2 * y * y) + 2 * d.p2 * x * y + r2 * (d.s3 + d.s4 * r2);
  out.dxdx = R + 2 * x * x * dR + 2 * d.p1 * y + 6 * d.p2 * x + 2 * x * (d.s1 + 2 * d.s2 * r2);
  out.dxdy = 2 * x * y * dR + 2 * d.p1 * x + 2 * d.p2 * y + 2 * y * (d.s1 + 2 * d.s2 * r2);
  out.dydx = 2 * x * y * dR + 2 * d.p1 * x + 2 * d.p2 * y + 2 * x * (d.s3 + 2 * d.s4 * r2);
  out.dydy = R + 2 * y * y * dR + 6 * d.p1 * y + 2 * d.p2 * x + 2 * y * (d.s3 + 2 * d.s4 * r2);
  return out;
}

// The radial map: the image radius of a ray at field angle θ (for the pinhole, of its radial
// part alone: the validity region is defined by it).
double image_radius(const LensModel& model, double theta) {
  return std::visit(
      [&](const auto& m) -> double {
        using M = std::decay_t<decltype(m)>;
        if constexpr (std::is_same_v<M, PinholeDistortion>) {
          double r = std::tan(theta);
          return r * radial(m, r * r).factor;
        } else if constexpr (std::is_same_v<M, KannalaBrandt>) {
          double t2 = theta * theta;
          return theta * (1 + t2 * (m.k1 + t2 * (m.k2 + t2 * (m.k3 + t2 * m.k4))));
        } else if constexpr (std::is_same_v<M, FThetaPolynomial>) {
          double r = 0;
          for (int i = 5; i >= 0; --i) r = (r + m.c[i]) * theta;
          return r;
        } else {
          switch (m.mapping) {
            case FisheyeMapping::equidistant:
              return theta;
            case FisheyeMapping::equisolid:
              return 2 * std::sin(theta / 2);
            case FisheyeMapping::stereographic:
              return 2 * std::tan(theta / 2);
            case FisheyeMapping::orthographic:
              return std::sin(theta);
          }
          return theta;
        }
      },
      model);
}

double reach(const LensModel& model) {
  if (std::holds_alternative<PinholeDistortion>(model)) return kPinholeReach;
  if (auto* c = std::get_if<ClassicFisheye>(&model)) {
    if (c->mapping == FisheyeMapping::stereographic) return kStereographicReach;
    if (c->mapping == FisheyeMapping::orthographic) return kPi / 2;
  }
  return kPi;
}

// Whether the radial map still grows at θ (and the pinhole's rational factor stays positive).
bool grows_at(const LensModel& model, double theta) {
  if (auto* d = std::get_if<PinholeDistortion>(&model)) {
    double r = std::tan(theta), r2 = r * r;
    Radial rad = radial(*d, r2);
    // d(r·R)/dr = R + 2 r² R'.
    return rad.denominator > 0 && rad.factor + 2 * r2 * rad.derivative > 0;
  }
  double h = 1e-7;
  double a = std::max(0.0, theta - h), b = theta + h;
  return image_radius(model, b) > image_radius(model, a);
}

// The inverse of the classic mappings in closed form; nothing for the others.
std::optional<double> classic_angle(const LensModel& model, double radius) {
  auto* c = std::get_if<ClassicFisheye>(&model);
  if (!c) return std::nullopt;
  switch (c->mapping) {
    case FisheyeMapping::equidistant:
      return radius;
    case FisheyeMapping::equisolid:
      return 2 * std::asin(std::min(1.0, radius / 2));
    case FisheyeMapping::stereographic:
      return 2 * std::atan(radius / 2);
    case FisheyeMapping::orthographic:
      return std::asin(std::min(1.0, radius));
  }
  return std::nullopt;
}

// Lens coefficients act on normalized image coordinates (radii of order 1): real calibrations,
// even of fisheyes, stay well within ±100. A coefficient of 1e300 parses, but its map squeezes
// the whole image onto the axis or past its valid field, and the frame renders black.
constexpr double kMaxLensCoefficient = 1e4;

void require_finite(const char* field, double v) {
  if (!std::isfinite(v))
    throw Error(std::string("camera.lens.") + field,
                "must be a finite number; got " + number_text(v));
  if (!(std::abs(v) <= kMaxLensCoefficient))
    throw Error(std::string("camera.lens.") + field,
                "must be within ±" + number_text(kMaxLensCoefficient) +
                    " (a lens coefficient that large images nothing); got " + number_text(v));
}

}  // namespace

const char* lens_model_name(const LensModel& model) {
  if (std::holds_alternative<PinholeDistortion>(model)) return "opencv";
  if (std::holds_alternative<KannalaBrandt>(model)) return "kannala-brandt";
  if (std::holds_alternative<FThetaPolynomial>(model)) return "ftheta";
  switch (std::get<ClassicFisheye>(model).mapping) {
    case FisheyeMapping::equidistant:
      return "equidistant";
    case FisheyeMapping::equisolid:
      return "equisolid";
    case FisheyeMapping::stereographic:
      return "stereographic";
    case FisheyeMapping::orthographic:
      return "orthographic-fisheye";
  }
  return "equidistant";
}

bool is_planar(const LensModel& model) {
  return std::holds_alternative<PinholeDistortion>(model);
}

void validate(const LensModel& model) {
  std::visit(
      [](const auto& m) {
        using M = std::decay_t<decltype(m)>;
        if constexpr (std::is_same_v<M, PinholeDistortion>) {
          const char* names[] = {"k1", "k2", "p1", "p2", "k3", "k4",    "k5",
                                 "k6", "s1", "s2", "s3", "s4", "tau_x", "tau_y"};
          double values[] = {m.k1, m.k2, m.p1, m.p2, m.k3, m.k4,    m.k5,
                             m.k6, m.s1, m.s2, m.s3, m.s4, m.tau_x, m.tau_y};
          for (int i = 0; i < 14; ++i) require_finite(names[i], values[i]);
          for (auto [name, tau] : {std::pair{"tau_x", m.tau_x}, std::pair{"tau_y", m.tau_y}})
            if (!(std::abs(tau) < kPi / 4))
              throw Error(std::string("camera.lens.") + name,
                          "sensor tilt must be within ±45° (radians); got " + number_text(tau));
        } else if constexpr (std::is_same_v<M, KannalaBrandt>) {
          for (auto [name, k] : {std::pair{"k1", m.k1}, std::pair{"k2", m.k2},
                                 std::pair{"k3", m.k3}, std::pair{"k4", m.k4}})
            require_finite(name, k);
        } else if constexpr (std::is_same_v<M, FThetaPolynomial>) {
          const char* names[] = {"c1", "c2", "c3", "c4", "c5", "c6"};
          for (int i = 0; i < 6; ++i) require_finite(names[i], m.c[i]);
        }
      },
      model);
  if (!grows_at(model, 1e-6))
    throw Error(std::string("camera.lens.") + lens_model_name(model),
                "the image radius must grow with the field angle near the axis (for f-theta: c1 "
                "> 0); this lens model folds over at once");
}

LensMap::LensMap(const LensModel& model, double max_field_angle_rad) : model_(model) {
  double limit = reach(model);
  if (max_field_angle_rad > 0) limit = std::min(limit, max_field_angle_rad);
  // Scan for the first field angle where the radial map stops growing, then narrow it down.
  double step = limit / kScanSteps, good = 0, bad = -1;
  for (int i = 1; i <= kScanSteps; ++i) {
    double theta = std::min(limit, i * step);
    if (!grows_at(model, theta)) {
      bad = theta;
      break;
    }
    good = theta;
  }
  if (bad > 0)
    for (int i = 0; i < 60; ++i) {
      double mid = 0.5 * (good + bad);
      (grows_at(model, mid) ? good : bad) = mid;
    }
  theta_max_ = bad > 0 ? good : limit;
  image_radius_max_ = image_radius(model, theta_max_);
  for (size_t i = 0; i < radius_table_.size(); ++i)
    radius_table_[i] = image_radius(model, theta_max_ * double(i) / (radius_table_.size() - 1));
  if (auto* d = std::get_if<PinholeDistortion>(&model)) {
    slope_max_ = std::tan(theta_max_);
    ideal_pinhole_ = *d == PinholeDistortion{};
    if (has_tilt(*d)) {
      Tilt t = tilt_matrix(d->tau_x, d->tau_y), inv = inverted(t);
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          tilt_[i * 3 + j] = t.m[i][j], inverse_tilt_[i * 3 + j] = inv.m[i][j];
    }
  }
}

std::optional<Point2d> LensMap::forward(Vector3d ray) const {
  double side = std::hypot(ray.x, ray.y);
  double theta = std::atan2(side, ray.z);
  if (!(theta <= theta_max_)) return std::nullopt;
  if (auto* d = std::get_if<PinholeDistortion>(&model_)) {
    if (!(ray.z > 0)) return std::nullopt;
    Point2d slope(ray.x / ray.z, ray.y / ray.z);
    if (ideal_pinhole_) return slope;
    Point2d p = distort(*d, slope).p;
    return has_tilt(*d) ? apply(tilt_, p) : p;
  }
  if (side == 0) return Point2d(0, 0);
  double r = image_radius(model_, theta);
  return Point2d(ray.x / side * r, ray.y / side * r);
}

std::optional<Vector3d> LensMap::pinhole_inverse(const PinholeDistortion& d, Point2d image,
                                                 const Point2d* start) const {
  const double r_max = slope_max_;
  Point2d target = has_tilt(d) ? apply(inverse_tilt_, image) : image;

  // 2. The undistorted radius whose radial image is the target's, by Newton's method on
  //    ρ(r) = r·R(r²) with its analytic slope R + 2r²R', kept inside [0, r_max] where ρ grows
  //    (one root); then Newton's method on the full map (tangential, prism terms) from there,
  //    halving a step whenever the residual does not shrink.
  const double target2 = target.x * target.x + target.y * target.y;
  const double target_radius = std::sqrt(target2);
  Point2d u = target;
  if (start) {
    u = *start;
  } else if (target_radius > 0) {
    double lo = 0, hi = std::min(r_max, 1e6), r = std::min(target_radius, hi);
    for (int i = 0; i < 60; ++i) {
      const double r2 = r * r;
      const Radial rad = radial(d, r2);
      const double f = r * rad.factor - target_radius;
      if (std::abs(f) <= 1e-15 * std::max(1.0, target_radius)) break;
      (f > 0 ? hi : lo) = r;
      double next = r - f / (rad.factor + 2 * r2 * rad.derivative);
      if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
      if (hi - lo <= 1e-16 * std::max(1.0, r)) break;
      r = next;
    }
    u = {target.x * (r / target_radius), target.y * (r / target_radius)};
  }
  auto residual2 = [&](Point2d q, Point2d& e) {
    Point2d f = distort(d, q).p;
    e = {f.x - target.x, f.y - target.y};
    return e.x * e.x + e.y * e.y;
  };
  Point2d e;
  double norm2 = residual2(u, e);
  const double scale2 = std::max(1.0, target2);
  for (int i = 0; i < 60 && norm2 > 1e-30 * scale2; ++i) {
    Distorted j = distort(d, u);
    double det = j.dxdx * j.dydy - j.dxdy * j.dydx;
    if (!(std::abs(det) > 0)) break;
    Point2d step((j.dydy * e.x - j.dxdy * e.y) / det, (j.dxdx * e.y - j.dydx * e.x) / det);
    double scale = 1, next_norm2 = norm2;
    Point2d next, next_e;
    for (int k = 0; k < 30; ++k, scale *= 0.5) {
      next = {u.x - scale * step.x, u.y - scale * step.y};
      next_norm2 = residual2(next, next_e);
      if (next_norm2 < norm2) break;
    }
    if (!(next_norm2 < norm2)) break;
    u = next;
    e = next_e;
    norm2 = next_norm2;
  }
  if (!(norm2 <= 1e-24 * scale2) || !(u.x * u.x + u.y * u.y <= r_max * r_max)) return std::nullopt;
  return normalize(Vector3d(u.x, u.y, 1));
}

std::optional<Vector3d> LensMap::inverse(Point2d image, Point2d start) const {
  if (auto* d = std::get_if<PinholeDistortion>(&model_); d && !ideal_pinhole_)
    if (auto ray = pinhole_inverse(*d, image, &start)) return ray;
  return inverse(image);  // no start, or one that did not lead to an accepted root
}

std::optional<Vector3d> LensMap::inverse(Point2d image) const {
  // 1. The field angle whose radial image is the target radius, from the table, then polished by
  //    Newton's method kept inside a shrinking bracket (the map grows over the region: one root).
  auto angle_of_radius = [&](double radius) -> std::optional<double> {
    if (!(radius <= image_radius_max_)) return std::nullopt;
    if (auto exact = classic_angle(model_, radius)) return std::min(*exact, theta_max_);
    size_t hi = std::upper_bound(radius_table_.begin(), radius_table_.end(), radius) -
                radius_table_.begin();
    hi = std::clamp<size_t>(hi, 1, radius_table_.size() - 1);
    double step = theta_max_ / double(radius_table_.size() - 1);
    double lo_theta = (hi - 1) * step, hi_theta = hi * step;
    double r0 = radius_table_[hi - 1], r1 = radius_table_[hi];
    double theta = r1 > r0 ? lo_theta + (radius - r0) / (r1 - r0) * step : lo_theta;
    for (int i = 0; i < 100; ++i) {
      double f = image_radius(model_, theta) - radius;
      if (std::abs(f) <= 1e-15 * std::max(1.0, radius)) return theta;
      (f > 0 ? hi_theta : lo_theta) = theta;
      double h = 1e-7 * std::max(1.0, theta);
      double slope = (image_radius(model_, theta + h) - image_radius(model_, theta - h)) / (2 * h);
      double next = theta - f / slope;
      if (!(next > lo_theta && next < hi_theta)) next = 0.5 * (lo_theta + hi_theta);
      if (hi_theta - lo_theta <= 1e-16 * std::max(1.0, theta)) return theta;
      theta = next;
    }
    return theta;  // the bracket is narrower than any use needs
  };

  if (auto* d = std::get_if<PinholeDistortion>(&model_)) {
    const double r_max = slope_max_;
    if (ideal_pinhole_) {  // no distortion: the image point is the ray's slope
      if (!(image.x * image.x + image.y * image.y <= r_max * r_max)) return std::nullopt;
      return normalize(Vector3d(image.x, image.y, 1));
    }
    return pinhole_inverse(*d, image, nullptr);
  }
  double radius = std::hypot(image.x, image.y);
  auto theta = angle_of_radius(radius);
  if (!theta) return std::nullopt;
  if (radius == 0) return Vector3d(0, 0, 1);
  double s = std::sin(*theta) / radius;
  return Vector3d(image.x * s, image.y * s, std::cos(*theta));
}

}  // namespace obscura
