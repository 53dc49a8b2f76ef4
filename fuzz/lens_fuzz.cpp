// libFuzzer target for lens prescription files (`--lens-file`, a scene's "lens_file"): the bytes
// are parsed as a prescription; one that parses becomes a lens system (first-order properties
// traced), is focused in a camera (exit-pupil bounds, best focus), and traces a few camera rays,
// chief rays and a projection. An obscura::Error is the expected outcome for bad input; anything
// else escaping, a crash, a sanitizer report, a leak or > 2 GB is a finding.
#include <cstdint>
#include <string>

#include "obscura/camera/camera.h"
#include "obscura/camera/lens_prescription_file.h"
#include "obscura/math/error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::string text(reinterpret_cast<const char*>(data), size);
  try {
    auto lens = std::make_shared<const obscura::LensSystem>(
        obscura::parse_lens_prescription(text, "fuzz.tsv", "fuzz"));
    // Focusing traces ~270,000 rays per surface set: keep inputs to lens-sized tables.
    if (lens->prescription().surfaces.size() > 40) return 0;
    obscura::Camera camera;
    obscura::LensSystemProjection projection;
    projection.lens = lens;
    camera.projection = projection;
    camera.film.width_px = 16;
    camera.film.height_px = 12;
    camera.lens.focus_distance_m = 2;
    camera.lens.aperture.blades = 6;
    camera.validate();
    obscura::PreparedCamera prepared = camera.prepare();
    for (obscura::Point2d p :
         {obscura::Point2d(8, 6), obscura::Point2d(1, 1), obscura::Point2d(15, 11)}) {
      prepared.generate_ray(p, {0.3, 0.7});
      if (auto world = prepared.unproject(p, 3)) prepared.project(*world);
    }
  } catch (const obscura::Error&) {
  }
  return 0;
}
