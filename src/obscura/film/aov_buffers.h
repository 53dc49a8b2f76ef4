// Auxiliary outputs (AOVs) beside the film: per pixel, what the camera rays met first, averaged
// over the pixel's samples (albedo, normal, depth, range) or taken from its first sample that hit
// something (id). Renderers write them tile by tile like the film (no locking needed).
//
// The names follow ground truth's (ground_truth_buffer.h): `depth` is the depth along the
// camera's optical axis (camera-space −z) for every projection — what Camera::project returns
// and unproject takes for the planar ones; `range` is the distance along the ray from its origin
// — what they take for the spherical ones (equirectangular, fisheye), whose rays start at the
// camera.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "obscura/color/rgb.h"
#include "obscura/film/image.h"
#include "obscura/math/vector.h"

namespace obscura {

// One AOV as an image, by the name its file carries (render.png → render.<name>.exr).
struct AovImage {
  std::string name;  // "albedo", "normal", "depth", "range", "id"
  Image image;
};

class AovBuffers {
 public:
  // Precondition: width > 0 and height > 0. Without `has_albedo` (a renderer that cannot tell a
  // surface's reflectance), albedo() is black and images() leaves it out.
  AovBuffers(int width, int height, bool has_albedo = true);

  int width() const { return width_; }
  int height() const { return height_; }
  bool has_albedo() const { return has_albedo_; }

  // One camera sample: whether it hit, and if so what. Misses count towards the mean (they
  // contribute zero albedo and normal, and no depth or range). `depth` along the optical axis,
  // `range` along the ray (m).
  void add_sample(Point2i pixel, bool hit, Rgb albedo, Normal3f normal, float depth, float range,
                  uint32_t id);
  // A pixel's final values, resolved elsewhere (the rasterizer's pixel centre, or another
  // process's part of the frame): the images return them unchanged, bit for bit. `depth` and
  // `range` are +∞ and `id` −1 where nothing was hit.
  void set_pixel(Point2i pixel, Rgb albedo, Vector3f normal, float depth, float range, int32_t id);

  Image albedo() const;  // RGB, the mean reflectance
  Image normal() const;  // RGB = world-space XYZ of the mean normal, renormalized
  Image depth() const;   // one channel "Z": mean depth along the optical axis over samples that
                         // hit (m), +∞ where none did
  Image range() const;   // one channel "range": mean distance along the ray over samples that
                         // hit (m), +∞ where none did
  Image id() const;      // one channel "id": the mesh index of the first sample that hit, −1
                         // where none did

  // The images in the order they are written: albedo (if it has one), normal, depth, range, id.
  // What gathering a frame's parts (MPI ranks, shard files) moves between processes.
  std::vector<AovImage> images() const;
  // The inverse of images(): buffers whose images are exactly `images` (names as images() gives
  // them, each of one size). Throws obscura::Error for a missing, unknown or misshaped image.
  static AovBuffers from_images(const std::vector<AovImage>& images);

 private:
  struct Pixel {
    Rgb albedo;
    Vector3f normal;
    double depth = 0, range = 0;
    int samples = 0, hits = 0;
    int32_t id = -1;
    bool resolved = false;  // set_pixel: the values are final, not sums
  };
  int width_, height_;
  bool has_albedo_;
  std::vector<Pixel> pixels_;
};

}  // namespace obscura
