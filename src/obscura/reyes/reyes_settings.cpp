#include "obscura/reyes/reyes_settings.h"

#include <cmath>
#include <sstream>

#include "obscura/math/error.h"

namespace obscura::reyes {

namespace {

std::string number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

void check_range(const char* option, double value, double low, double high, const char* unit) {
  // Written so that NaN fails: no comparison with it is true.
  if (!(value >= low && value <= high))
    throw Error(option, "must be in [" + number(low) + ", " + number(high) + "] " + unit +
                            "; got " + number(value));
}

}  // namespace

void validate(const ReyesSettings& s) {
  check_range("--reyes-shading-rate", s.shading_rate, kMinShadingRate, kMaxShadingRate,
              "pixels per micropolygon");
  check_range("--reyes-grid-size", s.grid_size, 1, reyes_knobs::kMaxGridSize, "micropolygons");
  check_range("--reyes-bucket-size", s.bucket_size, 1, kTileSize, "pixels");
  check_range("--reyes-pixel-samples", s.pixel_samples, 1, reyes_knobs::kMaxPixelSamples,
              "samples");
  check_range("--reyes-eye-splits", s.eye_splits, 0, reyes_knobs::kMaxEyeSplits, "splits");
  if (!(s.time_limit_s >= 0))
    throw Error("time limit", "must be ≥ 0 s; got " + number(s.time_limit_s));
  if (s.share.parts < 1 || s.share.part < 0 || s.share.part >= s.share.parts)
    throw Error("render", "part " + std::to_string(s.share.part) + " of " +
                              std::to_string(s.share.parts) + " does not exist");
}

std::vector<std::string> ReyesStats::lines() const {
  auto line = [](const char* name, double v) { return std::string(name) + ": " + number(v); };
  return {line("reyes pieces", double(pieces)),
          line("reyes grids", double(grids)),
          line("reyes micropolygons", double(micropolygons)),
          line("reyes shaded vertices", double(shaded_vertices)),
          line("reyes micropolygon area min (px)", area_min_px),
          line("reyes micropolygon area mean (px)", area_mean_px),
          line("reyes micropolygon area max (px)", area_max_px),
          line("reyes samples tested", double(samples_tested)),
          line("reyes samples hit", double(samples_hit)),
          line("reyes eye splits", double(eye_splits)),
          line("reyes eye-split culls", double(eye_split_culled)),
          line("reyes occlusion culls", double(occlusion_culled)),
          line("reyes displacement overruns", double(displacement_overruns)),
          line("reyes peak grids", double(peak_grids)),
          line("reyes peak grid bytes", double(peak_grid_bytes))};
}

}  // namespace obscura::reyes
