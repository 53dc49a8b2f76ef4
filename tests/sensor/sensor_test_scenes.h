// Scenes the sensor tests render: a flat field (a uniform environment seen through a pinhole,
// every pixel the same radiance) and a grey card filling the frame under a sun.
#pragma once

#include <string>

#include "obscura/film/image.h"
#include "obscura/io/json_scene.h"
#include "obscura/render/render_frame.h"

namespace obscura::test {

// The film of a pinhole camera looking into a uniform environment of radiance `radiance`: a
// flat field, as EMVA 1288 lights a sensor with a homogeneous source.
inline Image rendered_flat_field(int width, int height, double radiance) {
  std::string text = R"({"environment": {"color": )";
  text += std::to_string(radiance);
  text += R"(}, "cameras": [{"name": "c", "type": "perspective", "position": [0, 0, 0],
              "target": [0, 0, -1], "focal_length_mm": 50}]})";
  Scene scene = load_json_scene_text(text, "flat.json");
  scene.camera.film.width_px = width;
  scene.camera.film.height_px = height;
  FrameSettings settings;
  settings.samples_per_pixel = 1;
  return render_frame(scene, scene.camera, settings, false).finished();
}

}  // namespace obscura::test
