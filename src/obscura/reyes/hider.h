// The hider: one bucket's visibility samples and what each of them sees.
//
// Every pixel has its samples drawn in the camera's order (camera/camera_sample.h): a film
// point jittered as the pixel filter distributes it, a lens point and a time (with the pixel's
// rolling-shutter delay). Each micropolygon of a grid is tested against the samples near it,
// moved to each sample's time (camera space, linearly between the exposure's ends) and shifted
// by the thin lens for each sample's lens point: motion blur and depth of field cost visibility
// tests, never shading.
//
// A micropolygon is tested as two triangles with edge functions in double precision, computed
// from each edge's endpoints in one canonical order so that the two micropolygons sharing an
// edge see exactly opposite values, and a top-left rule gives a sample on the edge to one of
// them: neighbouring micropolygons (and grids, whose shared vertices are bit-identical) leave no
// crack and count no sample twice.
//
// Opaque surfaces keep the nearest hit per sample (ties go to the grid sampled first, in an
// order fixed for the frame, so the result does not depend on buckets or threads); α-blended
// surfaces add visible points to the sample's list, composited front to back by depth at the
// end, whatever order they came in.
#pragma once

#include <cstdint>
#include <vector>

#include "obscura/camera/camera.h"
#include "obscura/camera/camera_sample.h"
#include "obscura/color/rgb.h"
#include "obscura/math/bounds.h"
#include "obscura/math/vector.h"
#include "obscura/reyes/frame_view.h"
#include "obscura/reyes/grid.h"
#include "obscura/reyes/reyes_settings.h"

namespace obscura {
class AovBuffers;
class Film;
}  // namespace obscura

namespace obscura::reyes {

class ReyesScene;

// The scene triangle a pixel's first sample sees (ground truth): instance −1 where none.
struct SeenTriangle {
  int32_t instance = -1;
  uint32_t triangle = 0;
};

struct HiderCounts {
  uint64_t tested = 0, hit = 0;
};

class BucketHider {
 public:
  // `pixels` in film (crop) coordinates; `crop_min` the crop's corner in the full image.
  BucketHider(const FrameView& view, const CameraSampleOrder& order, const ReyesSettings& settings,
              Bounds2i pixels, Point2i crop_min);

  // Where its samples lie (raster coordinates of the full image).
  const RasterBounds& bounds() const { return bounds_; }
  // Whether every sample already sees an opaque surface nearer than `depth`: a grid no nearer
  // can change nothing, and is neither diced nor sampled (occlusion culling).
  bool hides(double depth);
  // Tests every micropolygon of `grid` against the samples it may cover.
  void sample(const Grid& grid, HiderCounts& counts);
  // Composites each sample's visible points and adds the samples to `film` (and `aovs`) pixel
  // by pixel, each pixel's samples in order.
  // With `seen` (one per film pixel, row-major), each pixel's first sample's nearest surface.
  void resolve(const ReyesScene& scene, const PreparedCamera& camera, bool needs_rays,
               float exposure, Film& film, AovBuffers* aovs, std::vector<SeenTriangle>* seen);

 private:
  struct SamplePoint {
    double x = 0, y = 0;  // raster, full image
    double tau = 0;       // fraction of the exposure interval
    double time_s = 0;
    Point2f lens_u = {};
    Point2d lens_m = {};  // the lens point, metres
    float weight = 1;
  };
  struct Visible {
    float depth = 0, range = 0;
    Rgb color = {};
    Vector3f normal = {};
    uint32_t mesh = 0;
    SeenTriangle surface = {};
  };
  struct Fragment {
    uint32_t sample = 0;
    float alpha = 0;
    uint64_t key = 0;  // grid key, then micropolygon: ties in depth resolved alike everywhere
    uint32_t micropolygon = 0;
    Visible point = {};
  };
  // The micropolygon's corners at one sample: raster position and depth.
  struct Corner {
    Point2d r;
    double depth;
  };

  struct Edge {
    double x = 0, y = 0, dx = 0, dy = 0;  // canonical start and direction
    bool negate = false, owned = false;
  };
  struct Triangle {
    Edge edges[3] = {};  // opposite corners 0, 1, 2
    double area = 0;     // twice the area, positive
    bool valid = false;
  };
  static Triangle set_up(Point2d a, Point2d b, Point2d c);
  static void set_up_quad(const Corner corners[4], Triangle triangles[2]);
  static bool inside(const Triangle& t, double px, double py, double w[3]);
  void test(const Grid& grid, uint32_t micropolygon, const Corner corners[4],
            const Triangle triangles[2], const int index[4], uint32_t sample, const SamplePoint& s,
            HiderCounts& counts);

  const FrameView& view_;
  Bounds2i pixels_;
  Point2i crop_min_;
  int per_pixel_ = 1;
  double margin_px_ = 0;  // how far samples stray outside their pixel
  RasterBounds bounds_;
  std::vector<SamplePoint> samples_;  // pixel-major, per_pixel_ each
  std::vector<uint32_t> by_time_;     // per pixel, its samples' indices by time (motion only)
  std::vector<Visible> nearest_;
  std::vector<uint8_t> opaque_hit_;
  size_t opaque_count_ = 0;  // samples with an opaque hit
  float farthest_ = 0;       // the farthest of their depths, when known
  bool farthest_known_ = false;
  std::vector<Fragment> fragments_;
};

}  // namespace obscura::reyes
