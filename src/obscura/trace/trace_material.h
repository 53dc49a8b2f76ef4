// A material as the tracer shades it: emitted radiance and the BSDF at a hit point, with
// textured parameters looked up at the hit's texture coordinates.
//
// Spectral mode (sampled_wavelengths.h): given the path's wavelengths, bsdf_at lifts each RGB
// input of the BSDF — albedos, tints, a conductor's η and k — to its spectrum's values at those
// wavelengths (rgb_to_spectrum.h) after textures and vertex colours have multiplied it, and the
// BSDF computes with them channel for channel: every BSDF here treats its three channels apart,
// so channel i is the BSDF at wavelength i. Lifting the inputs, not the BSDF's RGB result, keeps
// the products of colours inside a BSDF (a base colour times a Fresnel tint) spectral products.
#pragma once

#include <optional>
#include <vector>

#include "obscura/color/blackbody_spectrum.h"
#include "obscura/color/sampled_wavelengths.h"
#include "obscura/scene/material.h"
#include "obscura/scene/texture.h"
#include "obscura/trace/any_bsdf.h"
#include "obscura/trace/surface_hit.h"

namespace obscura {

class TraceMaterial {
 public:
  // A fixed BSDF (tests, tools).
  explicit TraceMaterial(AnyBsdf bsdf, Rgb emission = {}) : emission(emission), fixed_(bsdf) {}
  // Compiles a scene material; `textures` must outlive it.
  TraceMaterial(const Material& material, const std::vector<Texture>* textures);

  // The BSDF at `hit` (textures sampled at hit.uv; the base colour times hit.vertex_color). With
  // `wavelengths`, its colours are lifted to them and a dispersive dielectric takes the hero
  // wavelength's index; a fixed BSDF (first constructor) cannot be lifted and throws.
  AnyBsdf bsdf_at(const SurfaceHit& hit, const SampledWavelengths* wavelengths = nullptr) const;
  // A dielectric whose index depends on the wavelength: in spectral mode a path through it
  // keeps only its hero wavelength.
  bool disperses() const;
  // Emitted radiance at `hit`, from the front face only: `emission` times the emission texture.
  Rgb emitted(const SurfaceHit& hit) const;
  // Whether any light leaves the surface by itself (emission, or an unlit surface's colour).
  bool emits() const { return unlit_ || !emission.is_black(); }
  // Light leaving the surface by itself towards wo (unit, world, away from the surface): the
  // emission from the front face; for KHR_materials_unlit, its base colour (× texture × vertex
  // colour) from either face, to every ray — an unlit surface reflects nothing, so to the rest
  // of the scene it is a glowing surface (found by paths, not sampled as a light).
  Rgb emitted_towards(const SurfaceHit& hit, Vector3f wo) const;
  bool unlit() const { return unlit_; }
  // A blackbody emitter's spectral shape (Material::emission_kelvin), else null.
  const BlackbodySpectrum* emission_spectrum() const {
    return emission_spectrum_ ? &*emission_spectrum_ : nullptr;
  }

  // KHR_materials_volume: whether the surface bounds an absorbing volume, and the fraction of
  // light left after travelling `distance` inside it (Beer–Lambert: attenuation_color raised to
  // distance / attenuation_distance).
  bool absorbs_inside() const { return !absorption_.is_black(); }
  Rgb transmittance_inside(float distance) const;
  // The same at the path's wavelengths: the attenuation colour lifted, raised to the same power.
  Rgb transmittance_inside(float distance, const SampledWavelengths& wavelengths) const;
  // The emission factor (strength included): black for a material that never emits.
  Rgb emission;

  // glTF alpha coverage. Whether the material can let a ray through at all (alphaMode MASK or
  // BLEND), and whether it does at `hit`: MASK below the cutoff always, BLEND with probability
  // 1 − alpha, decided by `u` (uniform in [0, 1)). Alpha is the base colour factor's × the base
  // colour texture's × the vertex colour's (hit.vertex_alpha).
  bool has_alpha() const { return alpha_mode_ != AlphaMode::kOpaque; }
  bool passes_through(const SurfaceHit& hit, float u) const;

  // Tangent-space normal mapping (shading/normal_map.h): whether the material has a normal map,
  // and the perturbed unit normal at `hit` given the unit interpolated normal and the
  // interpolated tangent (xyz, w = handedness), all in world space.
  bool has_normal_map() const { return normal_texture_.valid() && textures_; }
  Vector3f normal_mapped(const SurfaceHit& hit, Vector3f normal, Vector4f tangent) const;
  // KHR_materials_clearcoat: whether the coat's normal can differ from the shading normal (the
  // base or the coat has a normal map), and the coat's unit normal at `hit` from the same
  // unperturbed normal and tangent: its own map's, or the unperturbed normal itself.
  bool has_coat_normal() const { return coat_normal_; }
  Vector3f coat_normal_mapped(const SurfaceHit& hit, Vector3f normal, Vector4f tangent) const;

 private:
  TextureRef emission_texture_;
  bool unlit_ = false;
  Rgb absorption_;  // σ_a per metre: −ln(attenuation_color) / attenuation_distance
  Rgb attenuation_color_{1.f};
  float attenuation_distance_ = 0;
  std::optional<BlackbodySpectrum> emission_spectrum_;
  TextureRef normal_texture_;
  float normal_scale_ = 1;
  bool coat_normal_ = false;
  AlphaMode alpha_mode_ = AlphaMode::kOpaque;
  float alpha_cutoff_ = 0.5f;
  float alpha_ = 1;           // the base colour factor's alpha
  TextureRef alpha_texture_;  // the base colour texture, whose alpha channel multiplies it
  std::optional<AnyBsdf> fixed_;
  MaterialModel model_;
  const std::vector<Texture>* textures_ = nullptr;
};

// Emitted radiance `rgb` at the path's wavelengths: a blackbody's spectrum with the luminance of
// `rgb` where `blackbody` is given, else `rgb` lifted as an illuminant.
Rgb lift_emission(Rgb rgb, const BlackbodySpectrum* blackbody,
                  const SampledWavelengths& wavelengths);

}  // namespace obscura
