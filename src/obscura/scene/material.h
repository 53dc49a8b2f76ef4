// Materials: a closed set of surface models (one std::variant, dispatched with std::visit) plus
// what every surface may have: emission and a normal map.
//
// Colours are linear RGB; a texture, where given, multiplies its factor (as glTF does).
#pragma once

#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <variant>

#include "obscura/color/rgb.h"
#include "obscura/scene/texture.h"

namespace obscura {

// Lambertian reflection.
struct DiffuseMaterial {
  Rgb reflectance{0.8f, 0.8f, 0.8f};  // albedo, each in [0, 1]
  TextureRef reflectance_texture;
};

// Phong / Blinn-Phong, as OBJ/MTL files describe surfaces (Ka, Kd, Ks, Ns, map_Kd).
struct PhongMaterial {
  Rgb ambient;                    // Ka: kept for the rasterizer's classic shading
  Rgb diffuse{0.8f, 0.8f, 0.8f};  // Kd
  Rgb specular;                   // Ks
  float shininess = 0;            // Ns: the specular exponent, ≥ 0
  TextureRef diffuse_texture;     // map_Kd
  bool blinn = true;              // half-vector (Blinn-Phong) rather than reflection (Phong) lobe
};

// A metal: complex index of refraction η + ik per RGB channel, GGX roughness.
struct ConductorMaterial {
  Rgb eta{0.2f, 0.92f, 1.1f};  // gold-like defaults
  Rgb k{3.9f, 2.45f, 2.14f};
  float roughness = 0;  // perceptual (GGX α = roughness²), in [0, 1]; 0 = mirror
};

// Glass, water: a smooth or rough dielectric interface.
struct DielectricMaterial {
  float ior = 1.5f;        // index of refraction inside, relative to outside (n_d, at 587.56 nm)
  float roughness = 0;     // as ConductorMaterial
  Rgb transmittance{1.f};  // tint of transmitted light
  // Dispersion: the Abbe number V_d = (n_d − 1) / (n_F − n_C) of the glass (BK7 64.2, dense
  // flint SF11 25.8), > 0; 0 = none, the index is `ior` at every wavelength. Only spectral mode
  // disperses; RGB mode uses `ior`.
  float abbe_number = 0;

  bool disperses() const { return abbe_number > 0; }
  // The index at a wavelength (nm): Cauchy's two-term n(λ) = A + B/λ² through n_d at the
  // Fraunhofer d line (587.56 nm) with n_F − n_C = (n_d − 1)/V_d (F 486.13, C 656.27 nm).
  float ior_at(float wavelength_nm) const;
};

// The glTF 2.0 metallic-roughness model, with KHR_materials_specular.
struct MetallicRoughnessMaterial {
  Rgb base_color{1.f};
  float alpha = 1;  // base colour alpha (coverage)
  TextureRef base_color_texture;
  float metallic = 1, roughness = 1;      // glTF defaults
  TextureRef metallic_roughness_texture;  // B = metallic, G = roughness (glTF)
  TextureRef occlusion_texture;           // R = ambient occlusion
  // KHR_materials_specular: strength and colour of the dielectric specular layer. A zero
  // specular makes a non-metal purely diffuse (Blender's exporter writes this for its Diffuse
  // BSDF).
  float specular = 1;
  Rgb specular_color{1.f};
  TextureRef specular_texture;        // its A channel multiplies `specular`
  TextureRef specular_color_texture;  // its RGB (sRGB-encoded) multiplies `specular_color`
  float ior = 1.5f;                   // KHR_materials_ior; glTF's default 1.5 gives F0 = 0.04
  // KHR_materials_unlit: the surface shows its base colour (× texture × COLOR_0) as it is, lit
  // by nothing and lighting nothing (docs/scene-format.md says what the tracer does with it).
  bool unlit = false;
  // KHR_materials_transmission: the fraction of the dielectric's non-reflected light that passes
  // through the surface instead of being diffused (× the texture's R).
  float transmission = 0;
  TextureRef transmission_texture;
  // KHR_materials_volume: a thickness > 0 makes the mesh the boundary of a closed volume that
  // refracts; 0 is a thin wall that refracts nothing. Inside, light keeps
  // attenuation_color^(distance / attenuation_distance) (Beer–Lambert; infinity: clear).
  float thickness = 0;
  Rgb attenuation_color{1.f};
  float attenuation_distance = std::numeric_limits<float>::infinity();
  // KHR_materials_clearcoat: a clear GGX layer (F0 0.04) on top of everything else, with its own
  // roughness and normal; its weight is clearcoat × the texture's R, its roughness
  // clearcoat_roughness × the roughness texture's G. Without a coat normal map the coat keeps
  // the mesh's own normal, even where the base has a normal map.
  float clearcoat = 0;
  TextureRef clearcoat_texture;
  float clearcoat_roughness = 0;
  TextureRef clearcoat_roughness_texture;
  TextureRef clearcoat_normal_texture;
  float clearcoat_normal_scale = 1;
  // KHR_materials_sheen: a Charlie sheen layer over the base (under the coat): colour × the
  // colour texture's RGB, roughness × the roughness texture's A. Black: no sheen.
  Rgb sheen_color{0.f};
  TextureRef sheen_color_texture;
  float sheen_roughness = 0;
  TextureRef sheen_roughness_texture;

  bool has_clearcoat() const { return clearcoat > 0; }
  bool has_sheen() const { return !sheen_color.is_black(); }
  bool purely_diffuse() const {
    return metallic == 0 && transmission == 0 && (specular == 0 || specular_color.is_black()) &&
           !has_clearcoat() && !has_sheen();
  }
  bool has_volume() const { return transmission > 0 && thickness > 0; }
};

// Emits Material::emission and reflects nothing (a light's surface, a black body).
struct EmissiveMaterial {};

using MaterialModel = std::variant<DiffuseMaterial, PhongMaterial, ConductorMaterial,
                                   DielectricMaterial, MetallicRoughnessMaterial, EmissiveMaterial>;

// glTF's alphaMode: how the base colour's alpha (factor × texture alpha) covers the surface.
// kMask: fully there where alpha ≥ alpha_cutoff, absent elsewhere; kBlend: a fraction alpha of
// the light meets the surface and the rest passes through it (a veil, a leaf's edge).
enum class AlphaMode { kOpaque, kMask, kBlend };

struct Material {
  std::string name;
  MaterialModel model = DiffuseMaterial{};
  // Emitted radiance (W·sr⁻¹·m⁻²) from the front face, strength included; the emission texture,
  // where given, multiplies it. Non-black emission makes the surface an area light.
  Rgb emission;
  // > 0: the emission is a blackbody's at this temperature (K): `emission` then holds its colour
  // (BlackbodySpectrum::working_rgb) times the strength, what RGB mode renders, and spectral mode
  // emits Planck's spectrum with that luminance. 0: the emission is its RGB colour.
  float emission_kelvin = 0;
  TextureRef emission_texture;
  TextureRef normal_texture;  // tangent-space normal map
  float normal_scale = 1;
  bool double_sided = true;  // glTF doubleSided; the tracer reflects on both sides regardless
  AlphaMode alpha_mode = AlphaMode::kOpaque;
  float alpha_cutoff = 0.5f;  // kMask only
  // Displacement along the surface's normal before shading (REYES; the tracer and the rasterizer
  // draw the surface undisplaced): `displacement` metres (world), times the displacement
  // texture's first channel (linear) where there is one. `displacement_bound` (≥ 0, metres) is
  // the most it may reach, what REYES grows a surface's bounds by before dicing; absent, the
  // largest the displacement and its texture can give.
  float displacement = 0;
  TextureRef displacement_texture;
  std::optional<float> displacement_bound;
};

// A Lambertian material, emitting where `emission` is not black: the common case of scenes built
// in code.
Material diffuse_material(std::string name, Rgb reflectance, Rgb emission = {});

// The normal map whose UV set the mesh's tangents are built for: the material's own, else its
// clear coat's (an invalid reference where it has neither).
const TextureRef& tangent_space_texture(const Material& material);

// "diffuse", "phong", "conductor", "dielectric", "metallic-roughness", "emissive": the names the
// JSON scene file uses.
std::string_view material_type_name(const MaterialModel& model);

}  // namespace obscura
