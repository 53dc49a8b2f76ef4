#include "image_command.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "display_options.h"
#include "image_limit_option.h"
#include "obscura/color/transfer.h"
#include "obscura/film/image_metrics.h"
#include "obscura/io/image_io.h"
#include "obscura/math/error.h"
#include "usage_error.h"

namespace obscura::app {

namespace {

struct ConvertOptions {
  std::string input, output;
  DisplayOptions display;
  bool quiet = false;
};

// Display-referred inputs (PNG, JPEG, TIFF) hold sRGB-encoded values; linearise them so that
// the output path (develop, or a linear format) sees light again. Alpha stays as it is.
void linearize_if_encoded(const std::string& path, Image& image) {
  if (!is_display_format(image_format_for_path(path))) return;
  for (size_t i = 0; i < image.data.size(); ++i) {
    bool alpha = image.channels == 4 && i % 4 == 3;
    if (!alpha) image.data[i] = decode(TransferFunction::kSrgb, image.data[i]);
  }
}

void run_convert(const ConvertOptions& o) {
  ImageWriteOptions write_options = image_write_options(o.display);
  check_output_path(o.output, "output");
  check_not_an_input(o.output, {o.input});
  Image image = read_image(o.input);
  try {
    image_format_for_path(o.input);
    linearize_if_encoded(o.input, image);
  } catch (const Error&) {
    // An input format Obscura does not write (e.g. .bmp) is read as linear values.
  }
  report_write(o.output, write_image(o.output, image, write_options), o.quiet);
  if (!o.quiet) std::printf("%s\n", o.output.c_str());
}

struct DiffOptions {
  std::string a, b, heatmap;
  bool json = false;
};

// A perceptually ordered black → red → yellow → white ramp for the heat map, as encoded sRGB.
Rgb heat_color(float t) {
  t = std::clamp(t, 0.f, 1.f);
  return {std::min(1.f, 3 * t), std::clamp(3 * t - 1, 0.f, 1.f), std::clamp(3 * t - 2, 0.f, 1.f)};
}

void run_diff(const DiffOptions& o) {
  if (!o.heatmap.empty()) {
    check_output_path(o.heatmap, "--heatmap");
    check_not_an_input(o.heatmap, {o.a, o.b});
  }
  Image a = read_image(o.a), b = read_image(o.b);
  if (a.width != b.width || a.height != b.height || a.channels != b.channels)
    throw Error(o.b, "cannot compare a " + std::to_string(b.width) + "x" +
                         std::to_string(b.height) + "x" + std::to_string(b.channels) +
                         " image with " + o.a + " (" + std::to_string(a.width) + "x" +
                         std::to_string(a.height) + "x" + std::to_string(a.channels) + ")");
  const ImageDifference diff = compare_images(a, b);
  const int channels = diff.channels;
  const double overall_mse = diff.mse(), overall_max = diff.max_abs_all();
  const size_t non_finite = diff.non_finite;

  auto name = [&](int c) {
    return c < int(a.channel_names.size()) ? a.channel_names[c] : "C" + std::to_string(c);
  };
  auto fmt = [](double v) {
    char buffer[32];
    if (std::isinf(v)) return std::string("inf");
    std::snprintf(buffer, sizeof buffer, "%.6g", v);
    return std::string(buffer);
  };
  if (o.json) {
    std::printf("{\"width\": %d, \"height\": %d, \"channels\": [", a.width, a.height);
    for (int c = 0; c < channels; ++c) {
      double mse = diff.mse(c);
      std::printf(
          "%s{\"name\": \"%s\", \"mse\": %s, \"rmse\": %s, \"psnr_db\": %s, \"max_abs\": %s}",
          c ? ", " : "", name(c).c_str(), fmt(mse).c_str(), fmt(std::sqrt(mse)).c_str(),
          std::isinf(psnr(mse)) ? "null" : fmt(psnr(mse)).c_str(),
          fmt(diff.max_abs[size_t(c)]).c_str());
    }
    std::printf(
        "], \"mse\": %s, \"rmse\": %s, \"psnr_db\": %s, \"max_abs\": %s, \"non_finite\": %zu}\n",
        fmt(overall_mse).c_str(), fmt(std::sqrt(overall_mse)).c_str(),
        std::isinf(psnr(overall_mse)) ? "null" : fmt(psnr(overall_mse)).c_str(),
        fmt(overall_max).c_str(), non_finite);
  } else {
    std::printf("%-8s %12s %12s %10s %12s\n", "channel", "MSE", "RMSE", "PSNR dB", "max |error|");
    for (int c = 0; c < channels; ++c) {
      double mse = diff.mse(c);
      std::printf("%-8s %12s %12s %10s %12s\n", name(c).c_str(), fmt(mse).c_str(),
                  fmt(std::sqrt(mse)).c_str(), fmt(psnr(mse)).c_str(),
                  fmt(diff.max_abs[size_t(c)]).c_str());
    }
    std::printf("%-8s %12s %12s %10s %12s\n", "all", fmt(overall_mse).c_str(),
                fmt(std::sqrt(overall_mse)).c_str(), fmt(psnr(overall_mse)).c_str(),
                fmt(overall_max).c_str());
    if (non_finite) std::printf("non-finite differences skipped: %zu\n", non_finite);
  }

  if (!o.heatmap.empty()) {
    // Per pixel: the largest channel error, scaled so that the image's largest error is white.
    Image heat(a.width, a.height, 3);
    const Image pixel_error = pixel_max_abs_difference(a, b);
    float scale = overall_max > 0 ? float(1 / overall_max) : 0.f;
    for (size_t p = 0; p < pixel_error.data.size(); ++p) {
      Rgb e = heat_color(pixel_error.data[p] * scale);
      for (int k = 0; k < 3; ++k) heat.data[3 * p + k] = decode(TransferFunction::kSrgb, e[k]);
    }
    write_image(o.heatmap, heat);
  }
}

}  // namespace

void add_image_command(CLI::App& app) {
  CLI::App* image = app.add_subcommand("image", "Convert and compare image files");
  image->require_subcommand(1);

  auto convert = std::make_shared<ConvertOptions>();
  CLI::App* c = image->add_subcommand(
      "convert",
      "Convert an image: linear inputs (EXR, HDR, PFM) are developed for display "
      "outputs (PNG, JPEG, TIFF, Y4M); 8/16-bit inputs are read as sRGB");
  c->add_option("input", convert->input, "Input image")->required()->check(CLI::ExistingFile);
  c->add_option("output", convert->output, "Output image; the format follows the extension")
      ->required();
  add_display_options(c, convert->display, /*with_exposure=*/true);
  add_max_image_pixels_option(c);
  c->add_flag("-q,--quiet", convert->quiet, "Print nothing on success");
  c->callback([convert] { run_convert(*convert); });

  auto diff = std::make_shared<DiffOptions>();
  CLI::App* d = image->add_subcommand(
      "diff",
      "Compare two images of the same size: MSE, RMSE, PSNR (peak 1) and max error per "
      "channel, on the values as stored (encoded for 8/16-bit files)");
  d->add_option("a", diff->a, "First image")->required()->check(CLI::ExistingFile);
  d->add_option("b", diff->b, "Second image")->required()->check(CLI::ExistingFile);
  d->add_option("--heatmap", diff->heatmap, "Write a heat map of the per-pixel error (PNG)");
  d->add_flag("--json", diff->json, "Machine-readable output");
  add_max_image_pixels_option(d);
  d->callback([diff] { run_diff(*diff); });
}

}  // namespace obscura::app
