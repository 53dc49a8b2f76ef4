// Auxiliary outputs (AOVs) beside the film: per pixel, what the camera rays met first, averaged
// over the pixel's samples (albedo, normal, depth) or taken from its first sample that hit
// something (id). Renderers write them tile by tile like the film (no locking needed).
#pragma once

#include <cstdint>
#include <vector>

#include "obscura/color/rgb.h"
#include "obscura/film/image.h"
#include "obscura/math/vector.h"

namespace obscura {

class AovBuffers {
 public:
  // Precondition: width > 0 and height > 0.
  AovBuffers(int width, int height);

  // One camera sample: whether it hit, and if so what. Misses count towards the mean (they
  // contribute zero albedo and normal, and no depth).
  void add_sample(Point2i pixel, bool hit, Rgb albedo, Normal3f normal, float depth, uint32_t id);

  Image albedo() const;  // RGB, the mean reflectance
  Image normal() const;  // RGB = world-space XYZ of the mean normal, renormalized
  Image depth() const;   // one channel "Z": mean distance along the ray over samples that hit
                         // (m), +∞ where none did
  Image id() const;      // one channel "id": the mesh index of the first sample that hit, −1
                         // where none did

 private:
  struct Pixel {
    Rgb albedo;
    Vector3f normal;
    double depth = 0;
    int samples = 0, hits = 0;
    int32_t id = -1;
  };
  int width_, height_;
  std::vector<Pixel> pixels_;
};

}  // namespace obscura
