// Depth of field as a post-process: one pass over a rendered colour image and its depth,
// blurring each pixel by the camera's circle of confusion, as real-time engines do when they
// cannot afford to render the scene many times (compare accumulation.h, which is exact).
//
// Scatter as gather: every pixel q is thought of as a disk of radius r_q = CoC(depth_q)/2
// (Camera::circle_of_confusion_px), of uniform density 1/area. Pixel p gathers the disks that
// cover it, with an antialiased edge (coverage = clamp(r_q + ½ − |q − p|, 0, 1), r_q ≥ ½ so a
// sharp pixel covers exactly itself), and two depth rules stop sharp things from smearing:
//   • a sample behind p spreads at most as far as p's own blur (r_q → min(r_q, r_p)): the
//     background cannot bleed over a sharp foreground, whose edges stay crisp;
//   • samples in front of p form a separate layer laid over p's own with opacity equal to the
//     summed coverage/area of their disks (clamped to 1), so a blurred foreground edge turns
//     half-transparent over what lies behind it instead of being averaged away.
// Near and behind are decided by relative depth, blended linearly over `depth_tolerance`, so
// a slanted surface is not split into layers at every pixel.
//
// Known artifacts (a single image and z-buffer cannot know what the foreground hides):
//   • a blurred foreground's silhouette spreads outwards over the background but stays opaque
//     on its inside: the background hidden behind it is not in the image, so the foreground
//     does not become partly transparent within its own outline (accumulation shows it);
//   • colours of surfaces visible only through the lens' edge (around thin foreground objects)
//     are missing for the same reason;
//   • the CoC is clamped to `max_coc_px` to bound the cost; larger blurs are too small;
//   • a pixel stands for one depth, so the pixels of an anti-aliased edge blur with the depth
//     of whichever surface covered its first sample;
//   • it must run on linear HDR (before develop): on tone-mapped values bright highlights lose
//     the weight that makes them bloom into bokeh disks;
//   • the bokeh is a round disk whatever the aperture's blades.
#pragma once

#include "obscura/camera/camera.h"
#include "obscura/film/image.h"

namespace obscura::raster {

struct PostDepthOfFieldSettings {
  // The largest circle of confusion honoured, in pixels (diameter); larger ones are clamped.
  // The cost per pixel grows with its square.
  double max_coc_px = 32;
  // Samples more than this fraction of p's depth nearer (farther) than p count fully as in
  // front of (behind) p; closer ones are blended linearly.
  double depth_tolerance = 0.05;
};

// `color`: linear RGB (≥ 3 channels, the first three used); `view_depth`: one channel, the
// distance along the camera's axis in metres (RenderTarget::view_depth_image: +∞ where nothing
// was drawn). Both have the same size; the image need not be the whole film (a crop window
// works: the CoC depends on depth only). Returns a 3-channel RGB image. Without depth of field
// on the camera the colour comes back unchanged. Deterministic and thread-count independent.
// Throws obscura::Error for mismatched sizes or channel counts, or bad settings.
Image depth_of_field_post(const Image& color, const Image& view_depth, const Camera& camera,
                          const PostDepthOfFieldSettings& settings = {});

// Each pixel's circle of confusion through `camera` (diameter in pixels, one channel "C") for
// the view depth (+∞: the limit at infinity): what the post-process blurs with.
Image circle_of_confusion_image(const Image& view_depth, const Camera& camera);

// The same post-process on circles of confusion given per pixel, so that it needs no camera:
// the parts of a frame carry them to where the whole frame is finished (render/frame_finish.h).
// `pixel_aspect`: the film's pixel width over height (FilmGeometry::pixel_aspect).
Image depth_of_field_post(const Image& color, const Image& view_depth, const Image& coc_px,
                          double pixel_aspect, const PostDepthOfFieldSettings& settings = {});

}  // namespace obscura::raster
