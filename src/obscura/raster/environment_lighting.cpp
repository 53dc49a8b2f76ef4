#include "obscura/raster/environment_lighting.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>
#include <optional>
#include <span>
#include <string>

#include "obscura/math/disk_cache.h"
#include "obscura/math/safe_index.h"

#ifndef OBSCURA_TABLE_KEY  // names this file's entries in the cache folder by the code that made
                           // them
#error "OBSCURA_TABLE_KEY comes from cmake/table_key.cmake"
#endif

namespace obscura::raster {

namespace {

constexpr float kPi = std::numbers::pi_v<float>;

// The tracer's equirectangular mapping (see draw_background) and its inverse.
Point2f equirect_uv(Vector3f d) {
  float theta = std::atan2(std::sqrt(d.x * d.x + d.z * d.z), d.y);
  float u = 0.5f + std::atan2(d.x, -d.z) / (2 * kPi);
  return {u - std::floor(u), theta / kPi};
}
Vector3f equirect_direction(float u, float v) {
  float phi = 2 * kPi * (u - 0.5f), theta = kPi * v;
  float s = std::sin(theta);
  return {s * std::sin(phi), std::cos(theta), -s * std::cos(phi)};
}

// Bilinear, wrapping around in u and clamped at the poles.
Rgb sample_bilinear(const Image& image, Point2f uv) {
  float x = uv.x * image.width - 0.5f,
        y = clamp_or_low(uv.y * image.height - 0.5f, 0.f, float(image.height - 1));
  // NaN-safe (math/safe_index.h): a NaN direction reads texel 0 with NaN weights.
  int x0 = floor_to_index(x), y0 = int(y);
  float fx = clamp_or_low(x - std::floor(x), 0.f, 1.f), fy = y - float(y0);
  int y1 = std::min(y0 + 1, image.height - 1);
  auto wrap = [&](int i) { return ((i % image.width) + image.width) % image.width; };
  int xa = wrap(x0), xb = wrap(x0 + 1);
  return (image.rgb(xa, y0) * (1 - fx) + image.rgb(xb, y0) * fx) * (1 - fy) +
         (image.rgb(xa, y1) * (1 - fx) + image.rgb(xb, y1) * fx) * fy;
}

// Half the size, each texel the mean of the four under it (radiance maps: no gamma).
Image downsample(const Image& image) {
  Image out(std::max(1, image.width / 2), std::max(1, image.height / 2), 3);
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x) {
      Rgb sum;
      for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i)
          sum += image.rgb(std::min(2 * x + i, image.width - 1),
                           std::min(2 * y + j, image.height - 1));
      out.set_rgb(x, y, sum * 0.25f);
    }
  return out;
}

// Trilinear in a chain of equirectangular levels (level 0 the finest).
Rgb sample_chain(const std::vector<Image>& chain, Point2f uv, float lod) {
  lod = std::clamp(lod, 0.f, float(chain.size() - 1));
  int l0 = int(lod);
  int l1 = std::min(l0 + 1, int(chain.size()) - 1);
  float t = lod - float(l0);
  Rgb a = sample_bilinear(chain[size_t(l0)], uv);
  return t > 0 ? a * (1 - t) + sample_bilinear(chain[size_t(l1)], uv) * t : a;
}

float radical_inverse(uint32_t bits) {
  bits = (bits << 16u) | (bits >> 16u);
  bits = ((bits & 0x55555555u) << 1u) | ((bits & 0xAAAAAAAAu) >> 1u);
  bits = ((bits & 0x33333333u) << 2u) | ((bits & 0xCCCCCCCCu) >> 2u);
  bits = ((bits & 0x0F0F0F0Fu) << 4u) | ((bits & 0xF0F0F0F0u) >> 4u);
  bits = ((bits & 0x00FF00FFu) << 8u) | ((bits & 0xFF00FF00u) >> 8u);
  return float(bits) * 0x1p-32f;
}

// The environment convolved with the GGX lobe of width α about each texel's direction r, with
// n = v = r: Σ L(l)·(n·l) / Σ (n·l) over GGX half-vector samples (Karis 2013). Each sample reads
// the source chain at the level whose texels cover the sample's share of solid angle
// (filtered importance sampling, GPU Gems 3 ch. 20), so 128 samples leave no visible noise.
Image prefilter(const std::vector<Image>& chain, int width, int height, float alpha) {
  Image out(width, height, 3);
  const float texel_solid_angle = 4 * kPi / float(chain[0].width * chain[0].height);
  const float a2 = alpha * alpha;
  tbb::parallel_for(0, height, [&](int y) {
    for (int x = 0; x < width; ++x) {
      const Vector3f n = equirect_direction((x + 0.5f) / width, (y + 0.5f) / height);
      const Vector3f up = std::abs(n.y) < 0.999f ? Vector3f(0, 1, 0) : Vector3f(1, 0, 0);
      const Vector3f tx = normalize(cross(up, n)), ty = cross(n, tx);
      Rgb sum;
      float weight = 0;
      for (int i = 0; i < EnvironmentLighting::kSamples; ++i) {
        const float u1 = (i + 0.5f) / EnvironmentLighting::kSamples, u2 = radical_inverse(i);
        const float cos_h = std::sqrt((1 - u1) / (1 + (a2 - 1) * u1));
        const float sin_h = std::sqrt(std::max(0.f, 1 - cos_h * cos_h));
        const float phi = 2 * kPi * u2;
        const Vector3f h = tx * (sin_h * std::cos(phi)) + ty * (sin_h * std::sin(phi)) + n * cos_h;
        const float n_dot_l = 2 * cos_h * cos_h - 1;
        if (n_dot_l <= 0) continue;
        const Vector3f l = h * (2 * cos_h) - n;
        // pdf(l) = D(h)·(n·h)/(4 v·h) = D(h)/4 with v = n.
        const float t = cos_h * cos_h * (a2 - 1) + 1;
        const float pdf = a2 / (kPi * t * t) / 4;
        const float sample_solid_angle = 1 / (EnvironmentLighting::kSamples * pdf);
        const float lod = 0.5f * std::log2(sample_solid_angle / texel_solid_angle) + 1;
        sum += sample_chain(chain, equirect_uv(l), lod) * n_dot_l;
        weight += n_dot_l;
      }
      out.set_rgb(x, y, weight > 0 ? sum / weight : Rgb());
    }
  });
  return out;
}

}  // namespace

std::array<float, 9> EnvironmentLighting::harmonics(Vector3f d) {
  const float x = d.x, y = d.y, z = d.z;
  return {0.282094792f,
          0.488602512f * y,
          0.488602512f * z,
          0.488602512f * x,
          1.092548431f * x * y,
          1.092548431f * y * z,
          0.315391565f * (3 * z * z - 1),
          1.092548431f * x * z,
          0.546274215f * (x * x - y * y)};
}

std::array<Rgb, 9> EnvironmentLighting::project(const Image& map) {
  // Each row's sum, in parallel; the rows added in order (the same result for any thread count).
  std::vector<std::array<Rgb, 9>> rows(size_t(map.height));
  tbb::parallel_for(0, map.height, [&](int y) {
    // A texel's exact solid angle: Δφ (cos θ_top − cos θ_bottom).
    const double t0 = std::numbers::pi * y / map.height,
                 t1 = std::numbers::pi * (y + 1) / map.height;
    const float solid_angle =
        float(2 * std::numbers::pi / map.width * (std::cos(t0) - std::cos(t1)));
    std::array<Rgb, 9> sum{};
    for (int x = 0; x < map.width; ++x) {
      const std::array<float, 9> ylm =
          harmonics(equirect_direction((x + 0.5f) / map.width, (y + 0.5f) / map.height));
      const Rgb l = map.rgb(x, y) * solid_angle;
      for (int k = 0; k < 9; ++k) sum[size_t(k)] += l * ylm[size_t(k)];
    }
    rows[size_t(y)] = sum;
  });
  std::array<Rgb, 9> total{};
  for (const auto& row : rows)
    for (size_t k = 0; k < 9; ++k) total[k] += row[k];
  return total;
}

EnvironmentLighting::EnvironmentLighting(Rgb uniform) : uniform_(uniform) {}

EnvironmentLighting::EnvironmentLighting(const Image& map, Rgb scale,
                                         const Transform& environment_from_world)
    : has_map_(true), environment_from_world_(environment_from_world) {
  Image source(map.width, map.height, 3);
  for (int y = 0; y < map.height; ++y)
    for (int x = 0; x < map.width; ++x) source.set_rgb(x, y, map.rgb(x, y) * scale);
  // The same map and scale always give the same tables: an earlier run's, from the cache folder,
  // spare the prefiltering (about a second for the studio map); the rotation is applied at lookup.
  const std::string name = cache_name(source);
  if (read_cache(name, source.width, source.height)) return;
  prepare(std::move(source));
  write_cache(name);
}

// Level 0 is the map box-filtered to at most 512 texels across; level k ≥ 1 is max(32, w₀ >> k)
// × half that (at least 16) — rough lobes are smooth.
std::array<std::pair<int, int>, EnvironmentLighting::kLevels> EnvironmentLighting::level_sizes(
    int width, int height) {
  while (width > 512) width = std::max(1, width / 2), height = std::max(1, height / 2);
  std::array<std::pair<int, int>, kLevels> sizes{};
  sizes[0] = {width, height};
  for (int k = 1; k < kLevels; ++k) {
    const int w = std::max(32, width >> k);
    sizes[size_t(k)] = {w, std::max(16, w / 2)};
  }
  return sizes;
}

void EnvironmentLighting::prepare(Image source) {
  // Irradiance: the cosine lobe's harmonic weights Â_l = π, 2π/3, π/4.
  const std::array<Rgb, 9> sh = project(source);
  constexpr float kBand[9] = {kPi,     2 * kPi / 3, 2 * kPi / 3, 2 * kPi / 3, kPi / 4,
                              kPi / 4, kPi / 4,     kPi / 4,     kPi / 4};
  for (size_t k = 0; k < 9; ++k) irradiance_sh_[k] = sh[k] * kBand[k];
  // Specular: a box-filtered chain from at most 512 texels across down to 8, then one
  // prefiltered level per roughness step (level_sizes).
  const auto sizes = level_sizes(source.width, source.height);
  std::vector<Image> chain{std::move(source)};
  while (chain.back().width > 512) chain.push_back(downsample(chain.back()));
  chain.erase(chain.begin(), chain.end() - 1);
  while (chain.back().width > 8 && chain.back().height > 4)
    chain.push_back(downsample(chain.back()));
  levels_.push_back(chain[0]);  // roughness 0: the mirror image
  for (int k = 1; k < kLevels; ++k) {
    const float roughness = float(k) / (kLevels - 1);
    levels_.push_back(prefilter(chain, sizes[size_t(k)].first, sizes[size_t(k)].second,
                                std::max(roughness * roughness, 1e-3f)));
  }
}

// The entry: the tables' code and compiler (OBSCURA_TABLE_KEY), then the scaled map's content.
std::string EnvironmentLighting::cache_name(const Image& source) {
  std::vector<float> header{float(source.width), float(source.height)};
  const uint64_t content = content_hash(std::as_bytes(std::span<const float>(source.data))) ^
                           content_hash(std::as_bytes(std::span<const float>(header)));
  return std::string("raster-environment-") + OBSCURA_TABLE_KEY + "-" + hex64(content) + ".bin";
}

// The entry's floats: the 9 irradiance coefficients (RGB), then every level's texels (RGB).
bool EnvironmentLighting::read_cache(const std::string& name, int width, int height) {
  const auto sizes = level_sizes(width, height);
  size_t count = 9 * 3;
  for (const auto& [w, h] : sizes) count += size_t(w) * h * 3;
  const std::optional<std::vector<std::byte>> bytes = read_cached_table(name, count * 4);
  if (!bytes) return false;
  std::vector<float> floats(count);
  std::memcpy(floats.data(), bytes->data(), bytes->size());
  const float* at = floats.data();
  for (Rgb& c : irradiance_sh_) c = Rgb(at[0], at[1], at[2]), at += 3;
  for (const auto& [w, h] : sizes) {
    Image level(w, h, 3);
    std::copy_n(at, level.data.size(), level.data.begin());
    at += level.data.size();
    levels_.push_back(std::move(level));
  }
  return true;
}

void EnvironmentLighting::write_cache(const std::string& name) const {
  std::vector<float> floats;
  for (const Rgb& c : irradiance_sh_) floats.insert(floats.end(), {c.r, c.g, c.b});
  for (const Image& level : levels_)
    floats.insert(floats.end(), level.data.begin(), level.data.end());
  write_cached_table(name, std::as_bytes(std::span<const float>(floats)));
}

Vector3f EnvironmentLighting::to_environment(Vector3f d) const {
  return normalize(environment_from_world_(d));
}

Rgb EnvironmentLighting::irradiance(Vector3f n) const {
  if (!has_map_) return uniform_ * kPi;
  const std::array<float, 9> ylm = harmonics(to_environment(n));
  Rgb e;
  for (size_t k = 0; k < 9; ++k) e += irradiance_sh_[k] * ylm[k];
  // The truncated series can dip below zero opposite a very bright, small source.
  return {std::max(e.r, 0.f), std::max(e.g, 0.f), std::max(e.b, 0.f)};
}

Rgb EnvironmentLighting::prefiltered(Vector3f d, float roughness) const {
  if (!has_map_) return uniform_;
  const Point2f uv = equirect_uv(to_environment(d));
  const float level = std::clamp(roughness, 0.f, 1.f) * (kLevels - 1);
  const int l0 = std::min(int(level), kLevels - 2);
  const float t = level - float(l0);
  return sample_bilinear(levels_[size_t(l0)], uv) * (1 - t) +
         sample_bilinear(levels_[size_t(l0 + 1)], uv) * t;
}

}  // namespace obscura::raster
