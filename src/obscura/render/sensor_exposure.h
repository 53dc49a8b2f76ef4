// What the raw sensor (sensor/sensor_capture.h) needs of the camera, as plain numbers: how long
// the photosites integrate, the ISO's gain, and the focal-plane exposure a film value of 1
// stands for. The film holds radiance × camera.exposure_scale(); the focal plane of a lens at
// f-number N receives E = q · L / N² (ISO 12232's q = 0.65: π/4 times lens transmittance,
// vignetting and cos⁴ — the calibration the physical exposure already uses), so a film value v
// is the exposure H = v · q · t / (N² · scale) lux·s. In physical mode that is 78 / S lux·s at
// v = 1: the saturation-based speed's definition, so the sensor saturates where the exposure
// says it should.
#pragma once

#include "obscura/camera/camera.h"
#include "obscura/sensor/sensor_capture.h"

namespace obscura {

// Throws obscura::Error when the camera's shutter does not stay open (the photosites would
// collect nothing) or its f-number is not positive.
SensorExposure sensor_exposure(const Camera& camera);

}  // namespace obscura
