// The calibration fuzz targets' input: the first byte picks the reader — 'y' OpenCV YAML, 'j'
// OpenCV JSON, 'n' NeRF transforms.json, 'c' COLMAP (the rest is cameras.txt, then, after a NUL
// byte when there is one, images.txt); any other byte modulo 4 in that order.
#pragma once

#include <string>

#include "obscura/io/colmap_model.h"
#include "obscura/io/nerf_transforms.h"
#include "obscura/io/opencv_calibration.h"

namespace obscura::fuzz {

inline CameraCalibration read_calibration(char selector, const std::string& text) {
  switch (selector) {
    case 'y':
      return parse_opencv_yaml(text, "fuzz.yaml");
    case 'j':
      return parse_opencv_json(text, "fuzz.json");
    case 'n':
      return parse_nerf_transforms(text, "transforms.json", "");
    case 'c':
      break;
    default:
      return read_calibration("yjnc"[static_cast<unsigned char>(selector) % 4], text);
  }
  size_t split = text.find('\0');
  if (split == std::string::npos)
    return parse_colmap_model(text, "cameras.txt", nullptr, "images.txt", "");
  std::string images = text.substr(split + 1);
  return parse_colmap_model(text.substr(0, split), "cameras.txt", &images, "images.txt", "");
}

}  // namespace obscura::fuzz
