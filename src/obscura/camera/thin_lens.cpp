#include "obscura/camera/thin_lens.h"

#include <cmath>
#include <string>

#include "obscura/math/error.h"
#include "obscura/math/number_text.h"

namespace obscura {

namespace {
constexpr double kMillimetresPerMetre = 1000;
}

double aperture_diameter_mm(const ThinLens& lens, double focal_length_mm) {
  return lens.aperture_diameter_mm ? *lens.aperture_diameter_mm : focal_length_mm / lens.f_number;
}

double effective_f_number(const ThinLens& lens, double focal_length_mm) {
  return focal_length_mm / aperture_diameter_mm(lens, focal_length_mm);
}

double image_distance_mm(double focal_length_mm, double focus_distance_m) {
  if (std::isinf(focus_distance_m)) return focal_length_mm;
  double s_f = focus_distance_m * kMillimetresPerMetre;
  return focal_length_mm * s_f / (s_f - focal_length_mm);
}

double circle_of_confusion_mm(const ThinLens& lens, double focal_length_mm, double depth_m) {
  if (!lens.depth_of_field) return 0;
  double a = aperture_diameter_mm(lens, focal_length_mm);
  double s = depth_m * kMillimetresPerMetre;
  double s_f = lens.focus_distance_m * kMillimetresPerMetre;
  if (std::isinf(s_f)) return a * focal_length_mm / s;  // the limit of the formula as S_f → ∞
  // The sensor at v = f·S_f/(S_f − f), or at f without breathing.
  double sensor_per_focus =
      lens.focus_breathing ? focal_length_mm / (s_f - focal_length_mm) : focal_length_mm / s_f;
  return a * std::abs(s - s_f) / s * sensor_per_focus;
}

void validate(const ThinLens& lens, double focal_length_mm) {
  if (!(lens.f_number > 0) || !std::isfinite(lens.f_number))
    throw Error("camera.f_number", "must be positive; got " + number_text(lens.f_number));
  if (lens.aperture_diameter_mm &&
      (!(*lens.aperture_diameter_mm > 0) || !std::isfinite(*lens.aperture_diameter_mm)))
    throw Error("camera.aperture_diameter_mm",
                "must be positive; got " + number_text(*lens.aperture_diameter_mm));
  if (!(lens.focus_distance_m > 0))
    throw Error("camera.focus_distance_m",
                "must be positive; got " + number_text(lens.focus_distance_m));
  if (lens.depth_of_field && !(lens.focus_distance_m * kMillimetresPerMetre > focal_length_mm))
    throw Error("camera.focus_distance_m",
                "must exceed the focal length (" + number_text(focal_length_mm) +
                    " mm) to focus; got " + number_text(lens.focus_distance_m) + " m");
  validate(lens.aperture);
  validate(lens.vignetting, aperture_diameter_mm(lens, focal_length_mm),
           lens.focus_distance_m * kMillimetresPerMetre);
}

}  // namespace obscura
