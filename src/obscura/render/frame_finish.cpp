#include "obscura/render/frame_finish.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "obscura/film/diffraction_psf.h"
#include "obscura/film/film.h"
#include "obscura/math/error.h"
#include "obscura/render/lens_flare.h"

namespace obscura {

namespace {

std::string hex(double value) {
  char text[40];
  std::snprintf(text, sizeof text, "%a", value);
  return text;
}

std::vector<std::string_view> split(std::string_view text, char separator) {
  std::vector<std::string_view> parts;
  for (size_t at = 0;;) {
    const size_t next = text.find(separator, at);
    parts.push_back(text.substr(at, next - at));
    if (next == std::string_view::npos) return parts;
    at = next + 1;
  }
}

// `count` finite numbers separated by commas (decimal or hex).
std::vector<double> numbers(std::string_view text, size_t count, const std::string& where,
                            std::string_view step) {
  std::vector<std::string_view> fields = split(text, ',');
  auto fail = [&] {
    return Error(where, std::string(step) + ": expected " + std::to_string(count) +
                            " numbers separated by commas; got '" + std::string(text) + "'");
  };
  if (fields.size() != count) throw fail();
  std::vector<double> values;
  for (std::string_view field : fields) {
    const std::string copy(field);
    char* end = nullptr;
    errno = 0;
    const double value = std::strtod(copy.c_str(), &end);
    if (copy.empty() || end != copy.c_str() + copy.size() || errno == ERANGE ||
        !std::isfinite(value))
      throw fail();
    values.push_back(value);
  }
  return values;
}

const Image& layer(const std::vector<AovImage>& layers, std::string_view name, int channels,
                   const Image& like) {
  for (const AovImage& l : layers)
    if (l.name == name) {
      if (l.image.channels != channels || l.image.width != like.width ||
          l.image.height != like.height)
        throw Error("finish_frame", "the '" + std::string(name) + "' layer must have " +
                                        std::to_string(channels) + " channels of " +
                                        std::to_string(like.width) + "x" +
                                        std::to_string(like.height) + " pixels");
      return l.image;
    }
  throw Error("finish_frame",
              "the frame has no '" + std::string(name) + "' layer, which its finishing needs");
}

Image channel(const Image& image, int c) {
  Image out(image.width, image.height, 1);
  for (size_t p = 0; p < out.data.size(); ++p) out.data[p] = image.data[p * image.channels + c];
  return out;
}

}  // namespace

std::string frame_finish_text(const FrameFinish& finish) {
  std::vector<std::string> steps;
  if (const auto& d = finish.depth_of_field)
    steps.push_back("dof=" + hex(d->pixel_aspect) + "," + hex(d->settings.max_coc_px) + "," +
                    hex(d->settings.depth_tolerance));
  if (finish.flare) steps.push_back("flare");
  if (const auto& g = finish.glare)
    steps.push_back("glare=" + std::to_string(g->aperture.blades) + "," +
                    hex(g->aperture.rotation_degrees) + "," + hex(g->f_number) + "," +
                    hex(g->pixel_width_mm) + "," + hex(g->pixel_height_mm) + "," +
                    hex(g->settings.strength) + "," + std::to_string(g->settings.radius_px));
  if (steps.empty()) return "none";
  std::string text;
  for (const std::string& step : steps) text += (text.empty() ? "" : ";") + step;
  return text;
}

FrameFinish parse_frame_finish(std::string_view text, const std::string& where) {
  FrameFinish finish;
  if (text == "none") return finish;
  for (std::string_view step : split(text, ';')) {
    const size_t equals = step.find('=');
    const std::string_view name = step.substr(0, equals);
    const std::string_view values =
        equals == std::string_view::npos ? std::string_view() : step.substr(equals + 1);
    if (name == "dof" && !finish.depth_of_field) {
      std::vector<double> v = numbers(values, 3, where, name);
      finish.depth_of_field = DepthOfFieldFinish{
          .pixel_aspect = v[0], .settings = {.max_coc_px = v[1], .depth_tolerance = v[2]}};
    } else if (name == "flare" && equals == std::string_view::npos && !finish.flare) {
      finish.flare = true;
    } else if (name == "glare" && !finish.glare) {
      std::vector<double> v = numbers(values, 7, where, name);
      if (v[0] != std::floor(v[0]) || v[0] < 0 || v[0] > 64 || v[6] != std::floor(v[6]) ||
          v[6] < 1 || v[6] > 4096)
        throw Error(where, "glare: blades and radius must be whole numbers in range; got '" +
                               std::string(values) + "'");
      finish.glare = GlareFinish{.aperture = {.blades = int(v[0]), .rotation_degrees = v[1]},
                                 .f_number = v[2],
                                 .pixel_width_mm = v[3],
                                 .pixel_height_mm = v[4],
                                 .settings = {.strength = v[5], .radius_px = int(v[6])}};
      validate(finish.glare->settings);
      if (!(v[2] > 0 && v[3] > 0 && v[4] > 0))
        throw Error(where, "glare: the f-number and pixel pitch must be positive; got '" +
                               std::string(values) + "'");
    } else {
      throw Error(where,
                  "expected 'none' or steps dof=…, flare, glare=… (each once) separated "
                  "by ';'; got '" +
                      std::string(step) + "'");
    }
  }
  return finish;
}

Image finish_frame(const Image& film_sums, const std::vector<AovImage>& layers,
                   const FrameFinish& finish, const std::atomic<bool>* cancel, bool* unfinished) {
  Image image = Film::from_sums(film_sums).to_image();
  if (const auto& dof = finish.depth_of_field) {
    const Image& inputs = layer(layers, kDepthOfFieldLayer, 2, image);
    image = raster::depth_of_field_post(image, channel(inputs, 0), channel(inputs, 1),
                                        dof->pixel_aspect, dof->settings);
  }
  if (finish.flare) {
    const Image& flare = layer(layers, kFlareLayer, 3, image);
    add_lens_flare(image, flare);
  }
  if (const auto& glare = finish.glare) {
    const Aperture aperture = glare->aperture;
    const DiffractionOptics optics{.pupil =
                                       [aperture](double x, double y) {
                                         return aperture_contains(aperture, {x, y});
                                       },
                                   .f_number = glare->f_number,
                                   .pixel_width_mm = glare->pixel_width_mm,
                                   .pixel_height_mm = glare->pixel_height_mm};
    validate(glare->settings);
    const int radius = glare_radius_px(glare->settings, image.width, image.height);
    // The cancel is looked at before the PSF, between its rows (the longest part at a large
    // radius) and between the convolution's channels.
    bool cancelled = cancel && cancel->load();
    if (!cancelled) {
      const Image psf = rgb_psf(optics, radius, cancel);
      cancelled =
          psf.data.empty() ||
          !convolve_with_psf(image, scale_scattered_light(psf, glare->settings.strength), cancel);
    }
    if (cancelled && unfinished) *unfinished = true;
  }
  return image;
}

}  // namespace obscura
