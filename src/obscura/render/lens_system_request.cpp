#include "obscura/render/lens_system_request.h"

#include <memory>
#include <string>
#include <vector>

#include "obscura/camera/builtin_lenses.h"
#include "obscura/io/lens_file.h"
#include "obscura/math/error.h"
#include "obscura/math/number_list.h"
#include "obscura/math/request_error.h"

namespace obscura {

bool apply_lens_system_overrides(Camera& camera, const CameraRequest& o) {
  if (o.lens && o.lens_file) throw RequestError("--lens and --lens-file: give one of them");
  if ((o.lens || o.lens_file) && o.projection)
    throw RequestError("--lens and --projection: a lens system is its own projection");
  if (o.lens || o.lens_file) {
    LensSystemProjection p;
    // A perspective camera's sensor carries over (its width; the height follows the image).
    if (auto* perspective = std::get_if<Perspective>(&camera.projection))
      p.sensor_width_mm = perspective->sensor_width_mm;
    if (o.lens) {
      try {
        p.lens = builtin_lens(*o.lens);
      } catch (const Error& e) {
        throw RequestError(std::string("--lens: ") + e.what());
      }
    } else {
      p.lens = std::make_shared<const LensSystem>(load_checked_lens_prescription(*o.lens_file));
    }
    camera.projection = p;
    camera.lens.depth_of_field = false;  // the lens system's own, not the thin lens's
  }
  auto* p = std::get_if<LensSystemProjection>(&camera.projection);
  if (!p) {
    if (o.lens_coating)
      throw RequestError("--lens-coating applies to a lens-system camera (--lens or --lens-file)");
    return false;
  }
  if (o.lens_coating) {
    try {
      p->coating = parse_lens_coating(*o.lens_coating, "--lens-coating");
    } catch (const Error& e) {
      throw RequestError(e.what());
    }
  }
  for (auto [given, option] : {std::pair{bool(o.fov_degrees), "--fov"},
                               {bool(o.horizontal_fov_degrees), "--hfov"},
                               {bool(o.focal_length_mm), "--focal-length"},
                               {bool(o.sensor_fit), "--sensor-fit"},
                               {bool(o.view_height_m), "--view-height"},
                               {bool(o.focus_breathing), "--focus-breathing"}})
    if (given)
      throw RequestError(
          std::string(option) +
          " does not apply to a lens-system camera (its lens sets the field of view)");
  if (o.sensor) {
    std::string text = *o.sensor;
    for (char& c : text)
      if (c == 'X') c = 'x';
    p->sensor_width_mm = parse_list(text, 'x', 2, "--sensor", "WxH in mm (36x24)")[0];
  }
  if (o.f_number) p->f_number = *o.f_number;
  if (o.focus_distance_m) camera.lens.focus_distance_m = *o.focus_distance_m;
  if (o.aperture_blades) camera.lens.aperture.blades = *o.aperture_blades;
  if (o.aperture_rotation_degrees)
    camera.lens.aperture.rotation_degrees = *o.aperture_rotation_degrees;
  return true;
}

}  // namespace obscura
