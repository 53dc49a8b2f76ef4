#include "obscura/film/aov_buffers.h"

#include <limits>
#include <string>

#include "obscura/math/error.h"

namespace obscura {

AovBuffers::AovBuffers(int width, int height, bool has_albedo)
    : width_(width), height_(height), has_albedo_(has_albedo) {
  if (width <= 0 || height <= 0)
    throw Error("AOV buffers", "need a positive size; got " + std::to_string(width) + "x" +
                                   std::to_string(height));
  pixels_.resize(size_t(width) * height);
}

void AovBuffers::add_sample(Point2i pixel, bool hit, Rgb albedo, Normal3f normal, float depth,
                            float range, uint32_t id) {
  Pixel& p = pixels_[size_t(pixel.y) * width_ + pixel.x];
  ++p.samples;
  if (!hit) return;
  ++p.hits;
  p.albedo += albedo;
  p.normal += to_vector(normal);
  p.depth += depth;
  p.range += range;
  if (p.id < 0) p.id = int32_t(id);
}

void AovBuffers::set_pixel(Point2i pixel, Rgb albedo, Vector3f normal, float depth, float range,
                           int32_t id) {
  Pixel& p = pixels_[size_t(pixel.y) * width_ + pixel.x];
  p = Pixel{.albedo = albedo,
            .normal = normal,
            .depth = depth,
            .range = range,
            .samples = 1,
            .hits = 1,
            .id = id,
            .resolved = true};
}

Image AovBuffers::albedo() const {
  Image image(width_, height_, 3);
  for (int y = 0; y < height_; ++y)
    for (int x = 0; x < width_; ++x) {
      const Pixel& p = pixels_[size_t(y) * width_ + x];
      image.set_rgb(x, y,
                    p.resolved      ? p.albedo
                    : p.samples > 0 ? p.albedo / float(p.samples)
                                    : Rgb());
    }
  return image;
}

Image AovBuffers::normal() const {
  Image image(width_, height_, 3);
  image.channel_names = {"X", "Y", "Z"};
  for (int y = 0; y < height_; ++y)
    for (int x = 0; x < width_; ++x) {
      const Pixel& p = pixels_[size_t(y) * width_ + x];
      Vector3f n = p.normal;
      float len = length(n);
      if (len > 0 && !p.resolved) n = n / len;
      image.set_rgb(x, y, {n.x, n.y, n.z});
    }
  return image;
}

namespace {

// The mean of a per-hit quantity (`sum` over `hits`), the resolved value itself, or +∞ (no hit).
float mean_over_hits(bool resolved, double sum, int hits) {
  return resolved   ? float(sum)
         : hits > 0 ? float(sum / hits)
                    : std::numeric_limits<float>::infinity();
}

}  // namespace

Image AovBuffers::depth() const {
  Image image(width_, height_, 1);
  image.channel_names = {"Z"};
  for (int y = 0; y < height_; ++y)
    for (int x = 0; x < width_; ++x) {
      const Pixel& p = pixels_[size_t(y) * width_ + x];
      image.at(x, y, 0) = mean_over_hits(p.resolved, p.depth, p.hits);
    }
  return image;
}

Image AovBuffers::range() const {
  Image image(width_, height_, 1);
  image.channel_names = {"range"};
  for (int y = 0; y < height_; ++y)
    for (int x = 0; x < width_; ++x) {
      const Pixel& p = pixels_[size_t(y) * width_ + x];
      image.at(x, y, 0) = mean_over_hits(p.resolved, p.range, p.hits);
    }
  return image;
}

Image AovBuffers::id() const {
  Image image(width_, height_, 1);
  image.channel_names = {"id"};
  for (int y = 0; y < height_; ++y)
    for (int x = 0; x < width_; ++x) image.at(x, y, 0) = float(pixels_[size_t(y) * width_ + x].id);
  return image;
}

std::vector<AovImage> AovBuffers::images() const {
  std::vector<AovImage> images;
  if (has_albedo_) images.push_back({"albedo", albedo()});
  images.push_back({"normal", normal()});
  images.push_back({"depth", depth()});
  images.push_back({"range", range()});
  images.push_back({"id", id()});
  return images;
}

AovBuffers AovBuffers::from_images(const std::vector<AovImage>& images) {
  auto find = [&](const std::string& name, int channels) -> const Image* {
    const Image* found = nullptr;
    for (const AovImage& aov : images)
      if (aov.name == name) found = &aov.image;
    if (found && found->channels != channels)
      throw Error("AOV image '" + name + "'", "expected " + std::to_string(channels) +
                                                  " channels; got " +
                                                  std::to_string(found->channels));
    return found;
  };
  for (const AovImage& aov : images)
    if (aov.name != "albedo" && aov.name != "normal" && aov.name != "depth" &&
        aov.name != "range" && aov.name != "id")
      throw Error("AOV image '" + aov.name + "'", "expected albedo, normal, depth, range or id");
  const Image* albedo = find("albedo", 3);
  const Image* normal = find("normal", 3);
  const Image* depth = find("depth", 1);
  const Image* range = find("range", 1);
  const Image* id = find("id", 1);
  if (!normal || !depth || !range || !id)
    throw Error("AOV images", "expected normal, depth, range and id images");
  const int width = normal->width, height = normal->height;
  for (const Image* image : {albedo, depth, range, id})
    if (image && (image->width != width || image->height != height))
      throw Error("AOV images", "expected every image of " + std::to_string(width) + "x" +
                                    std::to_string(height) + " pixels");
  AovBuffers buffers(width, height, albedo != nullptr);
  // Ids are mesh indices stored in a float channel: integers from −1 (nothing hit) up to 2^24,
  // the last integer a float holds exactly. Anything else did not come from a renderer.
  constexpr float largest_exact_id = 16777216.0f;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const float id_value = id->at(x, y, 0);
      if (!(id_value >= -1.0f && id_value <= largest_exact_id) ||
          id_value != float(int32_t(id_value)))
        throw Error("AOV image 'id'", "expected a whole mesh index from -1 to 16777216 at pixel (" +
                                          std::to_string(x) + ", " + std::to_string(y) + "); got " +
                                          std::to_string(id_value));
      buffers.set_pixel({x, y}, albedo ? albedo->rgb(x, y) : Rgb(),
                        {normal->at(x, y, 0), normal->at(x, y, 1), normal->at(x, y, 2)},
                        depth->at(x, y, 0), range->at(x, y, 0), int32_t(id_value));
    }
  return buffers;
}

}  // namespace obscura
