// A rolling shutter in the rasterizer. A matrix draws the whole frame at one time, but a rolling
// shutter exposes each sensor line at its own time (shutter.h), so the frame is drawn in bands of
// lines: each band whole, at the time of its middle line (mid-shutter + that line's delay), of
// which only the band's lines are kept.
//
// Error bound: a line's time is off by at most half a band's readout,
// (lines per band − 1) / 2 · line_time, so an image point moving at v px/s lands within
// v · (lines per band − 1) / 2 · line_time px of where the tracer (exact per line) puts it. With
// one band per line it is exact; the default of 64 bands keeps a 1080-line frame within 8 lines.
#pragma once

#include <functional>
#include <vector>

#include "obscura/camera/camera.h"
#include "obscura/film/film.h"
#include "obscura/film/image.h"

namespace obscura::raster {

// Draws `camera` (a global shutter) into `film` (the crop's size, one sample of weight 1 per
// pixel) and returns its per-pixel images (AOVs; crop-sized, any channels), possibly none.
using GlobalShutterDraw = std::function<std::vector<Image>(const Camera& camera, Film& film)>;

// The number of bands drawn for `camera`: one per line up to `max_bands`.
int rolling_band_count(const Camera& camera, int max_bands = 64);

// Draws a rolling-shutter `camera` band by band with `draw`, assembling the bands' lines into
// `film` and the returned images. `draw` gets the camera with a global shutter shifted by each
// band's delay.
std::vector<Image> draw_rolling_shutter(const Camera& camera, int bands,
                                        const GlobalShutterDraw& draw, Film& film);

}  // namespace obscura::raster
