// The raw sensor and the meter in `obscura render`: what happens before the frame is rendered
// (automatic exposure's metering pass, the sensor's resolution) and after (the capture, written
// as a DNG with its ground truth or developed to any other format).
#pragma once

#include <string>
#include <vector>

#include "obscura/film/image.h"
#include "obscura/io/image_io.h"
#include "obscura/scene/scene.h"
#include "render_options.h"

namespace obscura::app {

// Before the scene is loaded: `--exposure-mode auto` becomes a radiance-mode camera for the
// metering pass (its compensation kept for the program), and a .dng output turns the sensor on.
void take_sensor_requests(RenderOptions& options);

// After the scene and its camera are resolved: with automatic exposure, renders the metering
// pass (a few samples), meters it and sets the scene camera's exposure; then resolves the sensor
// (the scene camera's "sensor" block, then --raw-sensor's fields) and its exposure from the camera.
// Throws RequestError / obscura::Error for bad values.
void resolve_sensor(RenderOptions& options, Scene& scene);

// Adds the metered EV100 (and the auto exposure's choice) to a file's metadata.
void add_metering_metadata(const SensorOptions& sensor, ImageMetadata& metadata);

// Meters the finished frame (when --metering asks and no metering pass did) in scene luminance:
// the finished film divided by the camera's exposure scale.
void meter_finished(SensorOptions& sensor, const Image& finished, double exposure_scale);

// Writes the frame through the sensor: the DNG and its ground truth for a .dng output, else the
// developed image; returns the paths written (the image first). `seed` keys the temporal noise.
std::vector<std::string> write_sensor_frame(const RenderOptions& options, const std::string& output,
                                            const Image& finished, ImageWriteOptions write_options);

}  // namespace obscura::app
