#include "shard_file.h"

#include <algorithm>
#include <charconv>
#include <map>
#include <optional>

#include "obscura/io/image_io.h"
#include "obscura/math/error.h"
#include "usage_error.h"

namespace obscura::app {

namespace {

// Version 2 added the finishing layers and recipe (obscura:layers, obscura:finish); version 1
// parts, which have neither, are still read.
constexpr const char* kFormat = "obscura partial film 2";
constexpr const char* kFormatWithoutFinishing = "obscura partial film 1";
// obscura:aovs of a part without auxiliary images: an empty string attribute is not kept in an
// OpenEXR file (OpenImageIO drops it), and a missing one must stay an error.
constexpr const char* kNoAovs = "none";

bool parse_int(const std::string& text, int& value) {
  const char* end = text.data() + text.size();
  auto [at, error] = std::from_chars(text.data(), end, value);
  return error == std::errc() && at == end && !text.empty();
}

const char* end_name(RenderEnd end) {
  return end == RenderEnd::kInterrupted ? "interrupted"
         : end == RenderEnd::kTimeLimit ? "time limit"
                                        : "complete";
}

std::string attribute(const ImageMetadata& m, const std::string& path, const std::string& name) {
  for (const auto& [key, value] : m.attributes)
    if (key == name) return value;
  throw Error(path, "not a partial film of `obscura render --shard`: no " + name + " attribute");
}

int int_attribute(const ImageMetadata& m, const std::string& path, const std::string& name, int min,
                  int max) {
  int value = 0;
  std::string text = attribute(m, path, name);
  if (!parse_int(text, value) || value < min || value > max)
    throw Error(path, name + ": expected a whole number in [" + std::to_string(min) + ", " +
                          std::to_string(max) + "]; got '" + text + "'");
  return value;
}

// The channel names an auxiliary image is stored under: "albedo.R", … (its own names, or numbers).
std::vector<std::string> stored_channels(const AovImage& aov) {
  std::vector<std::string> names;
  for (int c = 0; c < aov.image.channels; ++c)
    names.push_back(aov.name + "." +
                    (size_t(c) < aov.image.channel_names.size() ? aov.image.channel_names[size_t(c)]
                                                                : std::to_string(c)));
  return names;
}

// "albedo=R,G,B;depth=Z" ↔ the auxiliary images' names and channels, in order (OpenEXR files
// keep channels sorted by name, so the order is kept here).
std::string aov_layout(const std::vector<AovImage>& aovs) {
  std::string layout;
  for (const AovImage& aov : aovs) {
    if (!layout.empty()) layout.push_back(';');
    layout.append(aov.name).push_back('=');
    std::vector<std::string> names = stored_channels(aov);
    for (size_t c = 0; c < names.size(); ++c) {
      if (c) layout.push_back(',');
      layout.append(names[c].substr(aov.name.size() + 1));
    }
  }
  return layout;
}

std::vector<AovImage> aov_images(const RenderedFrame& frame) {
  return frame.aovs ? frame.aovs->images() : std::vector<AovImage>();
}

std::string optional_attribute(const ImageMetadata& m, const std::string& name,
                               const std::string& otherwise) {
  for (const auto& [key, value] : m.attributes)
    if (key == name) return value;
  return otherwise;
}

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  if (text.empty()) return parts;
  for (size_t at = 0;;) {
    size_t next = text.find(separator, at);
    parts.push_back(text.substr(at, next - at));
    if (next == std::string::npos) return parts;
    at = next + 1;
  }
}

}  // namespace

ShardSpec parse_shard(const std::string& text) {
  size_t slash = text.find('/');
  ShardSpec spec;
  if (slash == std::string::npos || !parse_int(text.substr(0, slash), spec.part) ||
      !parse_int(text.substr(slash + 1), spec.parts) || spec.parts < 1 || spec.parts > 65536 ||
      spec.part < 0 || spec.part >= spec.parts)
    throw UsageError(
        "--shard: expected I/N, part I of N counted from 0 (0/4 … 3/4, N ≤ 65536); "
        "got '" +
        text + "'");
  return spec;
}

void write_shard(const std::string& path, const RenderedFrame& frame, ShardSpec spec,
                 const std::string& job) {
  const Image& sums = frame.film_sums;
  const std::vector<AovImage> aovs = aov_images(frame);
  // The auxiliary images, then the finishing layers: one list of channels after R, G, B, W.
  std::vector<AovImage> images = aovs;
  images.insert(images.end(), frame.layers.begin(), frame.layers.end());
  int channels = sums.channels;
  for (const AovImage& image : images) channels += image.image.channels;
  Image data(sums.width, sums.height, channels);
  data.channel_names = {"R", "G", "B", "W"};
  for (const AovImage& image : images)
    for (const std::string& name : stored_channels(image)) data.channel_names.push_back(name);
  for (size_t p = 0; p < size_t(sums.width) * sums.height; ++p) {
    float* out = &data.data[p * size_t(channels)];
    out = std::copy_n(&sums.data[p * 4], 4, out);
    for (const AovImage& image : images)
      out = std::copy_n(&image.image.data[p * size_t(image.image.channels)], image.image.channels,
                        out);
  }
  const TileDeal deal = tile_deal(frame.renderer, sums.width, sums.height, spec.parts);
  ImageMetadata metadata;
  metadata.description = "Part " + std::to_string(spec.part) + " of " + std::to_string(spec.parts) +
                         " of a frame (obscura render --shard); " +
                         "`obscura merge` assembles the parts";
  metadata.attributes = {
      {"obscura:format", kFormat},
      {"obscura:shard", std::to_string(spec.part) + "/" + std::to_string(spec.parts)},
      {"obscura:tile_size", std::to_string(deal.tile_size)},
      {"obscura:renderer", frame.renderer.name()},
      {"obscura:job", job},
      {"obscura:aovs", aovs.empty() ? kNoAovs : aov_layout(aovs)},
      {"obscura:layers", frame.layers.empty() ? kNoAovs : aov_layout(frame.layers)},
      {"obscura:finish", frame_finish_text(frame.finish)},
      {"obscura:end", end_name(frame.progress.end)},
      {"obscura:done", std::to_string(frame.progress.done)},
      {"obscura:requested", std::to_string(frame.progress.requested)},
      {"obscura:unit", frame.progress.unit}};
  write_exr_data(path, data, metadata);
}

ShardFile read_shard(const std::string& path) {
  ImageMetadata m;
  Image data = read_exr_data(path, m);
  const std::string format = attribute(m, path, "obscura:format");
  if (format != kFormat && format != kFormatWithoutFinishing)
    throw Error(path, "obscura:format: expected '" + std::string(kFormat) + "'");
  ShardFile shard;
  shard.path = path;
  std::string text = attribute(m, path, "obscura:shard");
  try {
    shard.spec = parse_shard(text);
  } catch (const UsageError&) {
    throw Error(path, "obscura:shard: expected I/N with 0 ≤ I < N; got '" + text + "'");
  }
  shard.job = attribute(m, path, "obscura:job");
  RenderedFrame& frame = shard.frame;
  const std::string renderer = attribute(m, path, "obscura:renderer");
  if (std::optional<Renderer> parsed = parse_renderer(renderer))
    frame.renderer = *parsed;
  else
    throw Error(path, "obscura:renderer: unknown renderer '" + renderer + "'");
  const int tile_size = int_attribute(m, path, "obscura:tile_size", 1, 1 << 20);
  if (tile_size != tile_deal(frame.renderer, 1, 1, 1).tile_size)
    throw Error(path, "obscura:tile_size: " + std::to_string(tile_size) + " is not the " +
                          renderer + " renderer's tiles");

  std::string end = attribute(m, path, "obscura:end");
  frame.progress.end = end == "interrupted"  ? RenderEnd::kInterrupted
                       : end == "time limit" ? RenderEnd::kTimeLimit
                       : end == "complete"
                           ? RenderEnd::kComplete
                           : throw Error(path,
                                         "obscura:end: expected complete, time limit or "
                                         "interrupted; got '" +
                                             end + "'");
  frame.progress.done = int_attribute(m, path, "obscura:done", 0, 1 << 30);
  frame.progress.requested = int_attribute(m, path, "obscura:requested", 1, 1 << 30);
  frame.progress.unit = attribute(m, path, "obscura:unit");

  // The channels: R, G, B, W, then each auxiliary image's, as obscura:aovs lists them, then
  // each finishing layer's, as obscura:layers lists them.
  auto parse_layout = [&](const std::string& key) {
    std::string text = optional_attribute(m, key, kNoAovs);
    if (text == kNoAovs) text.clear();
    std::vector<std::pair<std::string, std::vector<std::string>>> entries;
    for (const std::string& entry : split(text, ';')) {
      size_t equals = entry.find('=');
      std::vector<std::string> names = equals == std::string::npos
                                           ? std::vector<std::string>()
                                           : split(entry.substr(equals + 1), ',');
      if (equals == 0 || names.empty() || names.size() > 4)
        throw Error(path, key + ": expected name=channel,…;…; got '" + text + "'");
      entries.emplace_back(entry.substr(0, equals), names);
    }
    return entries;
  };
  attribute(m, path, "obscura:aovs");  // required, even when it says "none"
  const auto aov_entries = parse_layout("obscura:aovs");
  const auto layer_entries = parse_layout("obscura:layers");
  frame.finish = parse_frame_finish(optional_attribute(m, "obscura:finish", "none"),
                                    path + ": obscura:finish");
  std::vector<std::pair<std::string, std::vector<std::string>>> layout = aov_entries;
  layout.insert(layout.end(), layer_entries.begin(), layer_entries.end());
  int channels = 4;
  for (const auto& entry : layout) channels += int(entry.second.size());
  if (data.channels != channels)
    throw Error(path,
                "has " + std::to_string(data.channels) + " channels; its header (" +
                    (layout.empty() ? "no auxiliary images" : "obscura:aovs, obscura:layers") +
                    ") says " + std::to_string(channels));
  // OpenEXR keeps channels sorted by name: each is found by its name, not its position.
  auto column = [&](const std::string& name) {
    auto at = std::find(data.channel_names.begin(), data.channel_names.end(), name);
    if (at == data.channel_names.end())
      throw Error(path, "has no channel '" + name + "', which its header (obscura:aovs) names");
    return size_t(at - data.channel_names.begin());
  };
  const size_t pixels = size_t(data.width) * data.height;
  auto copy_channels = [&](const std::vector<std::string>& names, Image& into) {
    for (size_t c = 0; c < names.size(); ++c) {
      const size_t from = column(names[c]);
      for (size_t p = 0; p < pixels; ++p)
        into.data[p * names.size() + c] = data.data[p * size_t(channels) + from];
    }
  };
  frame.film_sums = Image(data.width, data.height, 4);
  frame.film_sums.channel_names = {"R", "G", "B", "W"};
  copy_channels(frame.film_sums.channel_names, frame.film_sums);
  // Each listed image from its channels "name.channel".
  auto read_images = [&](const auto& entries) {
    std::vector<AovImage> read;
    for (const auto& [name, names] : entries) {
      AovImage image{name, Image(data.width, data.height, int(names.size()))};
      image.image.channel_names = names;
      std::vector<std::string> stored;
      for (const std::string& channel : names) stored.push_back(name + "." + channel);
      copy_channels(stored, image.image);
      read.push_back(std::move(image));
    }
    return read;
  };
  const std::vector<AovImage> images = read_images(aov_entries);
  frame.layers = read_images(layer_entries);
  if (!images.empty()) {
    // Parts written before the range AOV had the range where depth now is (along the axis).
    if (std::none_of(images.begin(), images.end(),
                     [](const AovImage& image) { return image.name == "range"; }))
      throw Error(path,
                  "obscura:aovs: no range image: the part was written by an older obscura, "
                  "whose depth image was the range; render it again");
    try {
      frame.aovs = AovBuffers::from_images(images);
    } catch (const Error& e) {
      throw Error(path, std::string("obscura:aovs: ") + e.what());
    }
  }
  return shard;
}

void ShardMerger::add(ShardFile s) {
  if (!whole_) {
    paths_.emplace(s.spec.part, s.path);
    whole_ = std::move(s);
    return;
  }
  const ShardFile& first = *whole_;
  const int parts = first.spec.parts;
  auto differs = [&](const std::string& what) {
    return Error(s.path, "part " + std::to_string(s.spec.part) + " " + what + " than " +
                             first.path + " (part " + std::to_string(first.spec.part) + ")");
  };
  if (s.spec.parts != parts)
    throw differs("is one of " + std::to_string(s.spec.parts) + " parts, not " +
                  std::to_string(parts) + ":");
  if (s.job != first.job)
    throw differs("was rendered with other settings (scene, size, samples, seed, options)");
  if (s.frame.renderer != first.frame.renderer) throw differs("has another renderer");
  if (s.frame.film_sums.width != first.frame.film_sums.width ||
      s.frame.film_sums.height != first.frame.film_sums.height)
    throw differs("has another size");
  if (aov_layout(aov_images(s.frame)) != aov_layout(aov_images(first.frame)))
    throw differs("has other auxiliary images");
  if (aov_layout(s.frame.layers) != aov_layout(first.frame.layers) ||
      frame_finish_text(s.frame.finish) != frame_finish_text(first.frame.finish))
    throw differs("is finished otherwise (depth of field, flare, glare)");
  if (!paths_.emplace(s.spec.part, s.path).second)
    throw Error(s.path, "part " + std::to_string(s.spec.part) + " is given twice (also " +
                            paths_[s.spec.part] + ")");

  RenderedFrame& whole = whole_->frame;
  const int part = s.spec.part;
  const TileDeal deal =
      tile_deal(whole.renderer, whole.film_sums.width, whole.film_sums.height, parts);
  auto take = [&](const Image& from, Image& into) {
    unpack_owned_pixels(deal, part, pack_owned_pixels(deal, part, from), into);
  };
  take(s.frame.film_sums, whole.film_sums);
  if (whole.aovs) {
    std::vector<AovImage> whole_aovs = aov_images(whole);
    const std::vector<AovImage> aovs = aov_images(s.frame);
    for (size_t a = 0; a < whole_aovs.size(); ++a) take(aovs[a].image, whole_aovs[a].image);
    whole.aovs = AovBuffers::from_images(whole_aovs);
  }
  for (size_t l = 0; l < whole.layers.size(); ++l)
    take(s.frame.layers[l].image, whole.layers[l].image);
  // The least done and the most severe ending of any part.
  const RenderProgress& p = s.frame.progress;
  if (p.done != whole.progress.done && whole.progress.end == RenderEnd::kComplete)
    whole.progress.end = RenderEnd::kTimeLimit;
  whole.progress.done = std::min(whole.progress.done, p.done);
  whole.progress.end = std::max(whole.progress.end, p.end);
}

RenderedFrame ShardMerger::finish() {
  if (!whole_) throw Error("merge", "no parts given");
  const int parts = whole_->spec.parts;
  std::string missing;
  for (int p = 0; p < parts; ++p)
    if (!paths_.count(p)) missing += (missing.empty() ? "" : ", ") + std::to_string(p);
  if (!missing.empty())
    throw Error("merge", "parts of " + std::to_string(parts) + " missing: " + missing +
                             " (every part 0 … " + std::to_string(parts - 1) + " is needed once)");
  RenderedFrame whole = std::move(whole_->frame);
  whole_.reset();
  paths_.clear();
  return whole;
}

RenderedFrame merge_shards(const std::vector<ShardFile>& shards) {
  ShardMerger merger;
  for (const ShardFile& s : shards) merger.add(s);
  return merger.finish();
}

}  // namespace obscura::app
