#include "obscura/render/camera_glare.h"

#include <variant>

#include "obscura/camera/aperture.h"
#include "obscura/camera/lens_system_projection.h"
#include "obscura/camera/thin_lens.h"
#include "obscura/math/error.h"

namespace obscura {

DiffractionOptics diffraction_optics(const Camera& camera) {
  const Aperture aperture = camera.lens.aperture;
  DiffractionOptics optics{.pupil = [aperture](double x, double y) {
    return aperture_contains(aperture, {x, y});
  }};
  if (auto* lens_system = std::get_if<LensSystemProjection>(&camera.projection)) {
    // The sensor's width spans the image; the stop's f-number (the working one at infinity).
    double sensor_height_mm = lens_system->sensor_width_mm / camera.film.image_aspect();
    optics.f_number = camera.f_number();
    optics.pixel_width_mm = lens_system->sensor_width_mm / camera.film.width_px;
    optics.pixel_height_mm = sensor_height_mm / camera.film.height_px;
    return optics;
  }
  if (!std::holds_alternative<Perspective>(camera.projection))
    throw Error("glare",
                "needs a perspective or lens-system camera (its sensor gives the pixel pitch)");
  const double focal_length = camera.focal_length_mm();
  const Vector2d film_mm = camera.film_size_mm();
  optics.f_number = camera.image_distance_mm() / aperture_diameter_mm(camera.lens, focal_length);
  optics.pixel_width_mm = film_mm.x / camera.film.width_px;
  optics.pixel_height_mm = film_mm.y / camera.film.height_px;
  return optics;
}

GlareFinish glare_finish(const Camera& camera, const GlareSettings& settings) {
  validate(settings);
  const DiffractionOptics optics = diffraction_optics(camera);
  return {.aperture = camera.lens.aperture,
          .f_number = optics.f_number,
          .pixel_width_mm = optics.pixel_width_mm,
          .pixel_height_mm = optics.pixel_height_mm,
          .settings = settings};
}

Image glare_psf(const Camera& camera, const GlareSettings& settings) {
  validate(settings);
  return scale_scattered_light(rgb_psf(diffraction_optics(camera), settings.radius_px),
                               settings.strength);
}

void apply_glare(Image& image, const Camera& camera, const GlareSettings& settings) {
  GlareSettings bounded = settings;
  bounded.radius_px = glare_radius_px(settings, image.width, image.height);
  convolve_with_psf(image, glare_psf(camera, bounded));
}

}  // namespace obscura
