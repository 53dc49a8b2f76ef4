// Frame finishing: what turns a rendered film into the frame the user asked for, once the frame
// is whole — the rasterizer's post-process depth of field, ghost flares and diffraction glare, in
// that order (glare spreads whatever reaches the film, ghosts included; the post-process blurs
// what the lens images, before either).
//
// Every step needs the whole frame, so none can run on a part of it (an MPI rank's tiles, a
// `--shard` file). Each is therefore split in two: what depends on the scene and the camera is
// computed by whoever renders (a part computes it for its own pixels, or as plain numbers), and
// travels with the film — as per-pixel layers (the view depth and circle of confusion, the
// flare's light) and as a FrameFinish of plain numbers — to where the frame is assembled; there
// finish_frame applies it without a scene or a camera. One process, MPI ranks, shards + merge,
// sequences and Python all finish here, so they give the same frame bit for bit.
#pragma once

#include <atomic>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "obscura/camera/aperture.h"
#include "obscura/film/aov_buffers.h"
#include "obscura/film/glare.h"
#include "obscura/film/image.h"
#include "obscura/raster/depth_of_field_post.h"

namespace obscura {

// Diffraction glare as numbers (render/camera_glare.h takes them from a camera).
struct GlareFinish {
  Aperture aperture;  // the pupil's shape
  double f_number = 8, pixel_width_mm = 0.01, pixel_height_mm = 0.01;
  GlareSettings settings;
};

// The post-process depth of field: the film's pixel aspect (width over height) and its limits;
// the per-pixel view depth and circle of confusion come in the kDepthOfFieldLayer.
struct DepthOfFieldFinish {
  double pixel_aspect = 1;
  raster::PostDepthOfFieldSettings settings;
};

struct FrameFinish {
  std::optional<DepthOfFieldFinish> depth_of_field;  // needs the kDepthOfFieldLayer
  bool flare = false;                                // adds the kFlareLayer
  std::optional<GlareFinish> glare;

  bool any() const { return depth_of_field || flare || glare; }
};

// The per-pixel layers finishing reads, by name: "dof" (channels Z: distance along the camera's
// axis in metres, +∞ where nothing was drawn; C: circle of confusion, diameter in pixels) and
// "flare" (R, G, B: the ghosts' light in the film's units).
inline constexpr std::string_view kDepthOfFieldLayer = "dof";
inline constexpr std::string_view kFlareLayer = "flare";

// The recipe as one line of text for a file's header, and back, exactly (numbers as C99 hex
// floats): "none", or "dof=ASPECT,MAX_COC,TOLERANCE;flare;glare=BLADES,ROTATION,N,PW,PH,
// STRENGTH,RADIUS" with only the steps present. parse_frame_finish throws obscura::Error naming
// `where` and the part that is wrong.
std::string frame_finish_text(const FrameFinish& finish);
FrameFinish parse_frame_finish(std::string_view text, const std::string& where);

// The finished frame (linear RGB) from the whole frame's film sums (Film::sums) and layers.
// Throws obscura::Error when a step's layer is missing or misshaped. `cancel`, set from another
// thread (a signal handler) before the glare is done, leaves the glare out (the image holds the
// steps before it) and sets `*unfinished`.
Image finish_frame(const Image& film_sums, const std::vector<AovImage>& layers,
                   const FrameFinish& finish, const std::atomic<bool>* cancel = nullptr,
                   bool* unfinished = nullptr);

}  // namespace obscura
