// Metering and automatic exposure for a camera: a frame rendered in radiance units (the
// metering pass) is metered (film/metering.h, ISO 2720), and an exposure program
// (camera/exposure_program.h) sets the camera's f-number, shutter and ISO for a physical
// exposure at the metered EV100 less the compensation.
#pragma once

#include <optional>

#include "obscura/camera/camera.h"
#include "obscura/camera/exposure_program.h"
#include "obscura/film/image.h"
#include "obscura/film/metering.h"

namespace obscura {

struct MeteredExposure {
  MeteringMode mode = MeteringMode::kAverage;
  double luminance_cd_m2 = 0;  // what the pattern read
  double ev100 = 0;            // metered: log₂(L · 100 / 12.5)
  ExposureSettings settings;   // what the program chose for ev100 − compensation
};

// The camera as a metering pass renders it: radiance mode, no compensation (so its film is
// scene luminance where the optics pass all light).
Camera metering_camera(const Camera& camera);

// Meters `radiance_film` and runs the program for ev100 − `compensation_ev`, keeping the
// camera's f-number when it is fixed (a lens system's iris, an aperture given in mm). Throws
// obscura::Error when the frame is black (nothing to meter) or not finite.
MeteredExposure meter_for(const Camera& camera, const Image& radiance_film, MeteringMode mode,
                          double compensation_ev);

// Sets the camera to the program's choice: physical exposure, compensation 0, ISO, a shutter of
// the chosen length from its opening, and the f-number (when not fixed).
void apply_exposure(Camera& camera, const ExposureSettings& settings);

}  // namespace obscura
