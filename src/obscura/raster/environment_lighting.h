// Image-based lighting for the rasterizer, as real-time engines do it (Karis 2013, "Real Shading
// in Unreal Engine 4"; Filament; the glTF Sample Viewer): the environment's light reflected by a
// surface point is split into
//   diffuse   irradiance E(n)/π × the diffuse albedo, E from the environment's projection onto
//             the 9 real spherical harmonics of bands 0–2 (Ramamoorthi & Hanrahan 2001, "An
//             Efficient Representation for Irradiance Environment Maps": the clamped cosine keeps
//             over 99 % of its energy in those bands);
//   specular  the environment prefiltered by the GGX lobe about the mirror direction, assuming
//             n = v = r as the split sum does, one equirectangular level per roughness step and
//             linear between them, × the lobe's directional albedo (surface_material.h, from the
//             shading/ggx_energy tables, which are integrated numerically at startup).
// For a uniform environment both parts are exact (the prefilter's weights sum to one, a constant
// has only the l = 0 harmonic), so a convex object reflects exactly its directional albedo × L.
//
// Compiled once per SceneRasterizer (per scene and environment) and shared by every frame; the
// tables of a map at a scale are kept between runs in the cache folder (math/disk_cache.h), named
// by the scaled map's content and the code that prefilters it, so only the first run pays.
// Deterministic: every output texel is a fixed sum (a Hammersley set of lobe samples), and the
// harmonics are summed row by row in a fixed order, whatever the number of threads.
#pragma once

#include <array>
#include <string>
#include <utility>
#include <vector>

#include "obscura/color/rgb.h"
#include "obscura/film/image.h"
#include "obscura/math/transform.h"
#include "obscura/math/vector.h"

namespace obscura::raster {

class EnvironmentLighting {
 public:
  // Prefiltered levels: roughness 0, 0.2, …, 1 (glTF roughness, α = roughness²).
  static constexpr int kLevels = 6;
  // GGX samples per prefiltered texel (levels above 0).
  static constexpr int kSamples = 128;

  EnvironmentLighting() = default;  // black
  explicit EnvironmentLighting(Rgb uniform);
  // An equirectangular radiance map in the tracer's mapping (u = 0.5 along −Z growing towards +X,
  // v = θ/π from +Y) times `scale`, its directions given in environment space.
  EnvironmentLighting(const Image& map, Rgb scale, const Transform& environment_from_world);

  // Irradiance on a surface with unit world normal n (W/m² per unit radiance: π for L = 1).
  Rgb irradiance(Vector3f n) const;
  // The radiance about unit world direction d, averaged over a GGX lobe of this roughness.
  Rgb prefiltered(Vector3f d, float roughness) const;

  // The coefficients L_lm (order: l = 0; l = 1, m = −1, 0, 1; l = 2, m = −2 … 2) of a map's
  // radiance in its own space, each texel weighted by its exact solid angle.
  static std::array<Rgb, 9> project(const Image& map);
  // The real spherical harmonics Y_lm at unit direction d, in that order.
  static std::array<float, 9> harmonics(Vector3f d);

 private:
  Vector3f to_environment(Vector3f d) const;
  // The sizes of the levels a width × height map gives.
  static std::array<std::pair<int, int>, kLevels> level_sizes(int width, int height);
  void prepare(Image source);  // the tables from the scaled map
  static std::string cache_name(const Image& source);
  bool read_cache(const std::string& name, int width, int height);
  void write_cache(const std::string& name) const;
  Rgb uniform_;
  bool has_map_ = false;
  Transform environment_from_world_;
  std::array<Rgb, 9> irradiance_sh_{};  // L_lm × Â_l, so E(n) = Σ irradiance_sh_ · Y(n)
  std::vector<Image> levels_;           // prefiltered radiance, kLevels of them
};

}  // namespace obscura::raster
