#include "obscura/raster/rolling_shutter.h"

#include <algorithm>

#include "obscura/math/error.h"

namespace obscura::raster {

int rolling_band_count(const Camera& camera, int max_bands) {
  if (camera.shutter.line_time_s == 0) return 1;
  int lines = reads_rows(camera.shutter.readout) ? camera.film.height_px : camera.film.width_px;
  return std::clamp(lines, 1, std::max(1, max_bands));
}

std::vector<Image> draw_rolling_shutter(const Camera& camera, int bands,
                                        const GlobalShutterDraw& draw, Film& film) {
  const Bounds2i crop = camera.film.crop_pixels();
  if (film.width() != crop.width() || film.height() != crop.height())
    throw Error("draw_rolling_shutter", "the film must have the crop's size");
  const bool rows = reads_rows(camera.shutter.readout);
  const int lines = rows ? camera.film.height_px : camera.film.width_px;
  bands = std::clamp(bands, 1, lines);
  std::vector<Image> assembled;
  for (int b = 0; b < bands; ++b) {
    // Lines [first, last) in readout order: even shares of the sensor.
    const int first = int(int64_t(b) * lines / bands), last = int(int64_t(b + 1) * lines / bands);
    if (first == last) continue;
    // The band's image lines, in full-image coordinates, and their middle line's delay.
    const bool reversed = reads_backwards(camera.shutter.readout);
    const int lo = reversed ? lines - last : first, hi = reversed ? lines - first : last;
    const double middle = 0.5 * (lo + hi);  // raster coordinate of the band's centre
    const double delay = camera.readout_delay_s(rows ? Point2d(0, middle) : Point2d(middle, 0));
    // The crop's pixels on those lines.
    const int from = std::max(lo - (rows ? crop.min.y : crop.min.x), 0);
    const int to =
        std::min(hi - (rows ? crop.min.y : crop.min.x), rows ? crop.height() : crop.width());
    if (from >= to) continue;

    Camera global = camera;
    global.shutter.open_s += delay;
    global.shutter.close_s += delay;
    global.shutter.line_time_s = 0;
    Film band_film(film.width(), film.height());
    std::vector<Image> images = draw(global, band_film);
    const Image color = band_film.to_image();
    if (assembled.empty())
      for (const Image& image : images) {
        assembled.emplace_back(image.width, image.height, image.channels);
        assembled.back().channel_names = image.channel_names;
      }
    auto keep = [&](int x, int y) {
      film.add_sample({x, y}, color.rgb(x, y), 1.f);
      for (size_t i = 0; i < images.size() && i < assembled.size(); ++i)
        for (int c = 0; c < images[i].channels; ++c)
          assembled[i].at(x, y, c) = images[i].at(x, y, c);
    };
    for (int line = from; line < to; ++line)
      if (rows)
        for (int x = 0; x < crop.width(); ++x) keep(x, line);
      else
        for (int y = 0; y < crop.height(); ++y) keep(line, y);
  }
  return assembled;
}

}  // namespace obscura::raster
