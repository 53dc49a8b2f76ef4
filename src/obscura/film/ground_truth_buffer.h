// Per-pixel ground truth: exact values of the one surface point each pixel's centre sees, for
// computer-vision data sets (docs/ground_truth.md). Unlike the AOVs (aov_buffers.h), nothing is
// averaged: each renderer fills each pixel once, from its centre, at one reference time.
//
// Channels, in this order, named the way OpenImageIO names the channels of layers ("layer.X"):
//   Z                       depth along the camera's optical axis (m)
//   range                   distance from the centre ray's origin (the camera centre) (m)
//   P.X P.Y P.Z             world position
//   N.X N.Y N.Z             shading normal (world, unit)
//   Ng.X Ng.Y Ng.Z          geometric normal (world, unit, the front side of the winding)
//   instance                index of the mesh instance (an exact integer)
//   material                index of the material (an exact integer)
//   flow.forward.X/Y        optical flow to the second time (pixels, x right, y down)
//   flow.backward.X/Y       optical flow from the second time back to the first
//   time                    time of the pixel's ray (s)
// Misses (nothing seen): Z and range +∞, P, N, Ng and flow NaN, ids −1. Flow is NaN too where
// the point is not on the film at the other time (off the film, behind the camera, outside the
// near/far range).
#pragma once

#include <array>
#include <optional>
#include <string>

#include "obscura/film/image.h"
#include "obscura/math/vector.h"

namespace obscura {

// The channels' names, in the file's order.
inline constexpr std::array<const char*, 18> kGroundTruthChannels = {"Z",
                                                                     "range",
                                                                     "P.X",
                                                                     "P.Y",
                                                                     "P.Z",
                                                                     "N.X",
                                                                     "N.Y",
                                                                     "N.Z",
                                                                     "Ng.X",
                                                                     "Ng.Y",
                                                                     "Ng.Z",
                                                                     "instance",
                                                                     "material",
                                                                     "flow.forward.X",
                                                                     "flow.forward.Y",
                                                                     "flow.backward.X",
                                                                     "flow.backward.Y",
                                                                     "time"};

// What a pixel's centre ray meets at the reference time.
struct GroundTruthSurface {
  double z_m = 0, range_m = 0;
  Point3d position;
  Vector3d shading_normal, geometric_normal;  // unit
  int instance = -1, material = -1;
};

class GroundTruthBuffer {
 public:
  // Every pixel a miss, its time 0. Preconditions: width, height > 0.
  GroundTruthBuffer(int width, int height);

  int width() const { return image_.width; }
  int height() const { return image_.height; }

  void set_surface(int x, int y, const GroundTruthSurface& surface);
  // Flow in pixels; nothing where it is undefined (written as NaN).
  void set_forward_flow(int x, int y, std::optional<Vector2d> flow);
  void set_backward_flow(int x, int y, std::optional<Vector2d> flow);
  void set_time(int x, int y, double time_s);

  // Reading back (tests, tools): channel `name`'s value at (x, y); throws obscura::Error for an
  // unknown name.
  float value(int x, int y, const std::string& name) const;
  // Every channel, named: what image_io's write_exr_data writes.
  const Image& image() const { return image_; }

 private:
  Image image_;
};

// The index of channel `name` in kGroundTruthChannels, or −1.
int ground_truth_channel(const std::string& name);

}  // namespace obscura
