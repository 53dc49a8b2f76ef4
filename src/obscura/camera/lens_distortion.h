// Calibrated lens models: how a real camera's lens bends rays before they reach the sensor, in
// the parametrizations computer-vision toolboxes fit (OpenCV's pinhole and fisheye models, the
// polynomial f-theta model, the classic fisheye mappings). Each maps a ray direction to a point on
// the normalized image plane (the forward map) and back (the inverse map), inside a validity
// region where the forward map is one-to-one; docs/camera.md gives the equations beside OpenCV's.
//
// Frame: OpenCV's camera frame, X right, Y down, Z forward (Obscura's camera frame with Y and Z
// negated). "Normalized" image coordinates are pixels before the intrinsics K:
// u = fx·x + skew·y + cx, v = fy·y + cy (see calibrated_projection.h).
#pragma once

#include <array>
#include <optional>
#include <variant>

#include "obscura/math/vector.h"

namespace obscura {

// OpenCV's pinhole model (cv::projectPoints, cv::calibrateCamera) with its full coefficient set,
// in OpenCV's order (k1 k2 p1 p2 k3 k4 k5 k6 s1 s2 s3 s4 τx τy). With (x, y) = (X/Z, Y/Z), r² =
// x² + y²:
//   x' = x·(1 + k1 r² + k2 r⁴ + k3 r⁶)/(1 + k4 r² + k5 r⁴ + k6 r⁶) + 2 p1 x y + p2 (r² + 2x²)
//        + s1 r² + s2 r⁴
//   y' = y·(same ratio) + p1 (r² + 2y²) + 2 p2 x y + s3 r² + s4 r⁴
// then the sensor tilt τx, τy (radians; OpenCV's "tilted model" of Scheimpflug cameras). All zero
// is the ideal pinhole. Sees only rays with Z > 0.
struct PinholeDistortion {
  double k1 = 0, k2 = 0, p1 = 0, p2 = 0, k3 = 0, k4 = 0, k5 = 0, k6 = 0;
  double s1 = 0, s2 = 0, s3 = 0, s4 = 0;
  double tau_x = 0, tau_y = 0;
  bool operator==(const PinholeDistortion&) const = default;
};

// OpenCV's fisheye model (cv::fisheye), Kannala–Brandt with four coefficients: θ the angle between
// the ray and the optical axis,
//   θd = θ·(1 + k1 θ² + k2 θ⁴ + k3 θ⁶ + k4 θ⁸),  (x', y') = θd · (X, Y)/√(X² + Y²).
// Unlike cv::fisheye (which divides by Z), rays beyond 90° are mapped too: θ runs to 180°.
struct KannalaBrandt {
  double k1 = 0, k2 = 0, k3 = 0, k4 = 0;
  bool operator==(const KannalaBrandt&) const = default;
};

// The polynomial f-theta model of automotive and robotics fisheyes: the image radius (in the
// focal-length units of K) is a polynomial in θ without a constant term,
//   r(θ) = c1 θ + c2 θ² + c3 θ³ + c4 θ⁴ + c5 θ⁵ + c6 θ⁶,  (x', y') = r(θ) · (X, Y)/√(X² + Y²).
// c = (1, 0, …) is the equidistant fisheye; Kannala–Brandt is the odd-power special case.
struct FThetaPolynomial {
  std::array<double, 6> c = {1, 0, 0, 0, 0, 0};
  bool operator==(const FThetaPolynomial&) const = default;
};

// The four textbook fisheye mappings, r(θ) in focal-length units:
//   equidistant θ, equisolid 2 sin(θ/2), stereographic 2 tan(θ/2), orthographic sin θ.
enum class FisheyeMapping { equidistant, equisolid, stereographic, orthographic };
struct ClassicFisheye {
  FisheyeMapping mapping = FisheyeMapping::equidistant;
  bool operator==(const ClassicFisheye&) const = default;
};

using LensModel = std::variant<PinholeDistortion, KannalaBrandt, FThetaPolynomial, ClassicFisheye>;

// "opencv", "kannala-brandt", "ftheta", "equidistant", "equisolid", "stereographic",
// "orthographic-fisheye": the names the CLI and the JSON scene use.
const char* lens_model_name(const LensModel& model);

// True for the models whose rays all point forward (the pinhole); false for the fisheyes, which
// measure depth as distance, like the spherical cameras.
bool is_planar(const LensModel& model);

// Throws obscura::Error naming the first non-finite coefficient, or a model that has no valid
// region at all (its forward map turns back immediately).
void validate(const LensModel& model);

// A lens model with its validity region found once, ready for many rays.
//
// Validity region: the field angles θ ∈ [0, θmax) over which the model's radial map grows
// strictly (its derivative stays positive and, for the rational pinhole model, its denominator
// too), capped by the model's own reach (90° for the pinhole, 180° for the fisheyes, 90° for the
// orthographic fisheye) and by `max_field_angle` when set. Outside it a lens model folds over or
// turns back; rays beyond θmax are not seen (forward returns nothing) and image points beyond the
// region's image see nothing (inverse returns nothing), so forward and inverse are a bijection.
class LensMap {
 public:
  // `max_field_angle_rad` > 0 limits the field (a fisheye's 200° is 100° here); 0: the model's.
  explicit LensMap(const LensModel& model, double max_field_angle_rad = 0);

  const LensModel& model() const { return model_; }
  double max_field_angle() const { return theta_max_; }  // radians
  // The largest normalized image radius the valid region reaches along the image axes (for
  // sizing images that cover it).
  double max_image_radius() const { return image_radius_max_; }

  // Ray (OpenCV frame, any length > 0) → normalized image point; nothing outside the region.
  std::optional<Point2d> forward(Vector3d ray) const;
  // Normalized image point → unit ray (OpenCV frame); nothing outside the region's image or when
  // the iterative solve does not converge to 1e-12 (it is bounded: never a stall).
  std::optional<Vector3d> inverse(Point2d image) const;
  // The same with a starting guess for the pinhole model's undistorted point (x, y) = (X/Z, Y/Z)
  // near the answer (from a table of exact inverses): Newton's method then needs a step or two.
  // The result is accepted by the same tests, so it is the same ray to the solver's tolerance.
  std::optional<Vector3d> inverse(Point2d image, Point2d start) const;

 private:
  std::optional<Vector3d> pinhole_inverse(const PinholeDistortion& d, Point2d image,
                                          const Point2d* start) const;

  LensModel model_;
  double theta_max_ = 0;
  double image_radius_max_ = 0;
  // The radial map r(θ) tabulated over the valid region: the inverse's starting guess.
  std::array<double, 65> radius_table_{};
  double slope_max_ = 0;        // pinhole: tan θmax, the largest undistorted radius
  bool ideal_pinhole_ = false;  // the pinhole model with every coefficient 0: no solve needed
  // OpenCV's tilt matrix and its inverse, row by row (pinhole with τx or τy ≠ 0).
  std::array<double, 9> tilt_{}, inverse_tilt_{};
};

}  // namespace obscura
