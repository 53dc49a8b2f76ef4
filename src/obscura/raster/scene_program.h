// The programs that draw a scene's instances: object-space vertices in, exposed linear radiance
// out, shading each material with the scene's lights (surface_material.h).
//
//   ScenePixelProgram    per-pixel shading (Phong shading, the default), or per-face normals
//                        (flat); the geometric normal comes from the screen-space derivatives of
//                        the world position, so no per-face data is needed
//   SceneGouraudProgram  lighting at the vertices, interpolated; textures modulate it per pixel
//   WithCoverage<P>      P for a material with glTF alpha (MASK, BLEND): adds its coverage
//   DepthCoverageProgram depth only, with coverage (cut-out shadows)
#pragma once

#include <span>

#include "obscura/math/shading_normal.h"
#include "obscura/raster/clip_transform.h"
#include "obscura/raster/environment_lighting.h"
#include "obscura/raster/fragment_textures.h"
#include "obscura/raster/lights.h"
#include "obscura/raster/shaders.h"
#include "obscura/raster/shadow_map.h"
#include "obscura/raster/surface_material.h"
#include "obscura/raster/varyings.h"
#include "obscura/shading/material_point.h"
#include "obscura/shading/normal_map.h"

namespace obscura::raster {

// One frame's shadow maps, parallel to LightSet::directional and ::spot (shorter or empty: the
// remaining lights cast no shadows).
struct FrameShadows {
  std::span<const ShadowMap> directional, spot;
};

// The frame as drawn before the transmissive surfaces (exposed radiance, one colour per pixel,
// row-major over the target), which those surfaces show through them; null before it exists.
struct BehindImage {
  const Rgb* pixels = nullptr;
  int width = 0;
};

// What every draw of one instance shares.
struct InstanceUniforms {
  Matrix4f clip_from_object;
  Matrix4f world_from_object;
  Matrix4f normal_from_object;  // the inverse transpose of world_from_object's linear part
  float handedness = 1;         // −1 where world_from_object mirrors: tangent w flips with it
  // The eye: a point (perspective) or, for orthographic views, the direction towards the viewer.
  Point3f eye;
  Vector3f to_viewer;
  bool eye_at_infinity = false;
  const LightSet* lights = nullptr;
  FrameShadows shadows;
  const SurfaceMaterial* material = nullptr;
  float exposure = 1;        // the camera's exposure scale, applied to everything drawn
  bool flat = false;         // flat shading: the face normal instead of the interpolated one
  bool force_blinn = false;  // shade Phong materials with the half-vector lobe
  BehindImage behind;        // for KHR_materials_transmission

  OBSCURA_RASTER_INLINE Vector3f view_direction(Point3f p) const {
    return eye_at_infinity ? to_viewer : normalize(eye - p);
  }
  OBSCURA_RASTER_INLINE Point3f world_point(Point3f p) const {
    const auto& m = world_from_object.m;
    return {m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z + m[0][3],
            m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z + m[1][3],
            m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z + m[2][3]};
  }
  OBSCURA_RASTER_INLINE Vector3f world_normal(Vector3f n) const {
    return normal_from_object.apply_to_vector(n);
  }
};

// The environment's light reflected towards v (image-based lighting: environment_lighting.h).
OBSCURA_RASTER_INLINE Rgb environment_light(const SurfacePoint& s, const LightSet& lights,
                                            Vector3f n, Vector3f v) {
  const float n_dot_v = dot(n, v);
  const EnvironmentResponse r = environment_response(s, n_dot_v);
  if (!lights.environment)
    return (r.diffuse + r.specular + r.transmitted + r.coat) * lights.ambient;
  const EnvironmentLighting& env = *lights.environment;
  Rgb c;
  if (!r.diffuse.is_black()) c += r.diffuse * env.irradiance(n) * kBrdfInvPi;
  if (!r.specular.is_black()) c += r.specular * env.prefiltered(n * (2 * n_dot_v) - v, r.roughness);
  if (!r.transmitted.is_black()) c += r.transmitted * env.prefiltered(-v, r.roughness);
  if (!r.coat.is_black()) {
    const Vector3f coat_n = s.coat_normal == Vector3f() ? n : s.coat_normal;
    c += r.coat * env.prefiltered(coat_n * (2 * dot(coat_n, v)) - v, r.coat_roughness);
  }
  return c;
}

// Light reflected towards v at p by a surface point with unit normal n (facing v); `geometric`
// is the true surface's normal facing v: light from behind it is blocked, as in the tracer.
OBSCURA_RASTER_INLINE Rgb shade_surface(const SurfacePoint& s, const LightSet& lights,
                                        const FrameShadows& shadows, Point3f p, Vector3f n,
                                        Vector3f geometric, Vector3f v) {
  Rgb sum = environment_light(s, lights, n, v);
  auto add = [&](const IncidentLight& in, const ShadowMap* shadow) {
    if (dot(geometric, in.to_light) <= 0) return;
    Rgb r = in.strength * reflected_cosine(s, n, v, in.to_light);
    if (shadow && !r.is_black()) r = r * shadow->visibility(p, geometric);
    sum += r;
  };
  for (size_t i = 0; i < lights.directional.size(); ++i)
    add(incident(lights.directional[i], p),
        i < shadows.directional.size() ? &shadows.directional[i] : nullptr);
  for (const PointLight& l : lights.point) add(incident(l, p), nullptr);
  for (size_t i = 0; i < lights.spot.size(); ++i)
    add(incident(lights.spot[i], p), i < shadows.spot.size() ? &shadows.spot[i] : nullptr);
  for (const SurfaceLight& l : lights.surface) add(incident(l, p), nullptr);
  return sum;
}

// KHR_materials_transmission as glTF's real-time viewers draw it, split as the tracer's
// TransmissiveMetallicRoughnessBsdf splits it: (1 − w)·opaque + w·glass with w = (1 − metallic)·T,
// `opaque` the material at metallic/(1 − w) and `glass` a thin dielectric wall that reflects
// lights and surround with the dielectric Fresnel F and the GGX lobe, and lets (1 − F) × base
// colour of `behind` (the radiance drawn behind it, unexposed) through. Behind is looked up at
// the fragment's own pixel: no refraction offset and no blur for rough glass.
OBSCURA_RASTER_INLINE Rgb shade_transmissive(const SurfacePoint& s, const LightSet& lights,
                                             const FrameShadows& shadows, Point3f p, Vector3f n,
                                             Vector3f geometric, Vector3f v, Rgb behind) {
  const float w = std::clamp((1 - s.metallic) * s.transmission, 0.f, 1.f);
  SurfacePoint glass = s;
  glass.model = SurfaceModel::kDielectric;
  glass.alpha = std::max(s.alpha, kMinHighlightAlpha);
  glass.transmittance = Rgb(0.f);  // the light let through is `behind`, added here
  const float f = shading::fresnel_dielectric_from_outside(dot(n, v), s.ior);
  Rgb c =
      (shade_surface(glass, lights, shadows, p, n, geometric, v) + behind * s.base * (1 - f)) * w;
  if (w < 1) {
    SurfacePoint opaque = s;
    opaque.metallic = s.metallic / (1 - w);
    c += shade_surface(opaque, lights, shadows, p, n, geometric, v) * (1 - w);
  }
  return c;
}

OBSCURA_RASTER_INLINE Vector3f face_towards(Vector3f n, Vector3f v) {
  return dot(n, v) < 0 ? -n : n;
}

struct ScenePixelProgram {
  using Vertex = MeshVertex;  // object space
  struct Varyings {
    Point3f position;  // world
    Vector3f normal;   // world, interpolated (not unit)
    float u, v;
    Rgb color;
    float u1, v1;      // TEXCOORD_1
    Vector3f tangent;  // world, interpolated; zero without a normal map
    float tangent_w;   // handedness, in world space
  };
  InstanceUniforms uniforms;

  VertexOutput<Varyings> vertex(const MeshVertex& m) const {
    Vector3f t =
        uniforms.world_from_object.apply_to_vector({m.tangent.x, m.tangent.y, m.tangent.z});
    return {uniforms.clip_from_object(m.position),
            {uniforms.world_point(m.position), uniforms.world_normal(m.normal), m.uv.x, m.uv.y,
             m.color, m.uv1.x, m.uv1.y, t, m.tangent.w * uniforms.handedness}};
  }

  // Out of line: the material model is far larger than the tile loop around it, and inlined into
  // each of the loop's copies (scalar and 8-lane, baseline and AVX2) it took minutes to compile.
  OBSCURA_RASTER_OUTLINE Rgb fragment(const Varyings& a, const Varyings& dx, const Varyings& dy,
                                      FragmentInfo info) const {
    const SurfaceMaterial& m = *uniforms.material;
    Vector3f v = uniforms.view_direction(a.position);
    // The plane of the triangle from the derivatives of the position; facing the viewer.
    Vector3f geometric = cross(Vector3f(dx.position.x, dx.position.y, dx.position.z),
                               Vector3f(dy.position.x, dy.position.y, dy.position.z));
    float g2 = dot(geometric, geometric);
    Vector3f interpolated = a.normal;
    float i2 = dot(interpolated, interpolated);
    geometric = g2 > 0 ? geometric / std::sqrt(g2) : interpolated / std::sqrt(std::max(i2, 1e-30f));
    geometric = face_towards(geometric, v);
    FragmentUvs uvs{{{a.u, a.v, dx.u, dx.v, dy.u, dy.v}, {a.u1, a.v1, dx.u1, dx.v1, dy.u1, dy.v1}}};
    const FragmentTextures textures(m.textures, m.filter, uvs);
    Vector3f n = geometric, coat = geometric;
    if (!uniforms.flat && i2 > 0) {  // the tracer's convention (math/shading_normal.h)
      Vector3f shading = interpolated / std::sqrt(i2);
      // KHR_materials_clearcoat: the coat ignores the base's normal map; it has its own or none.
      if (m.model == SurfaceModel::kLayeredMetallicRoughness)
        coat =
            visible_shading_normal(coat_normal(m, shading, geometric, a, textures), geometric, v);
      if (textures.has(m.normal_texture)) {
        // Perturbed in the frame of the unperturbed normal and kept above the surface on its
        // side, as the tracer does; a back face then flips the whole frame (glTF doubleSided).
        Vector3f side = dot(shading, geometric) < 0 ? -geometric : geometric;
        shading = shading::keep_above_surface(
            shading::normal_mapped(m.normal_texture, m.normal_scale, shading,
                                   {a.tangent.x, a.tangent.y, a.tangent.z, a.tangent_w}, textures),
            side);
      }
      n = visible_shading_normal(shading, geometric, v);
    }

    SurfacePoint s = surface_point(m, uvs, a.color);
    s.coat_normal = coat;
    if (uniforms.force_blinn && s.model == SurfaceModel::kPhong) {
      s.model = SurfaceModel::kBlinnPhong;
      s.lobe_normalization = shading::blinn_phong_lobe_normalization(s.shininess);
    }
    Rgb c;
    if (s.model == SurfaceModel::kUnlit) {
      c = s.base;
    } else if (s.transmission > 0 && s.model == SurfaceModel::kMetallicRoughness) {
      // Behind is exposed radiance (the surround stands in where none was drawn yet).
      const BehindImage& b = uniforms.behind;
      Rgb behind = b.pixels && uniforms.exposure > 0
                       ? b.pixels[size_t(info.y) * size_t(b.width) + size_t(info.x)] *
                             (1 / uniforms.exposure)
                       : uniforms.lights->ambient;
      c = shade_transmissive(s, *uniforms.lights, uniforms.shadows, a.position, n, geometric, v,
                             behind);
    } else {
      c = shade_surface(s, *uniforms.lights, uniforms.shadows, a.position, n, geometric, v);
    }
    if (info.front_facing) c += shading::textured(m.emission, m.emission_texture, textures);
    return c * uniforms.exposure;
  }

  // The shading normal facing the viewer (world space), for the normal output.
  Vector3f normal(const Varyings& a) const {
    float i2 = dot(a.normal, a.normal);
    if (i2 <= 0) return {};
    return face_towards(a.normal / std::sqrt(i2), uniforms.view_direction(a.position));
  }

 private:
  // The clear coat's unit normal: the `unperturbed` shading normal, or its own normal map's
  // perturbation of it, kept above the surface like the base's.
  OBSCURA_RASTER_INLINE static Vector3f coat_normal(const SurfaceMaterial& m, Vector3f unperturbed,
                                                    Vector3f geometric, const Varyings& a,
                                                    const FragmentTextures& textures) {
    const MetallicRoughnessMaterial& mr = m.metallic_roughness;
    if (!mr.has_clearcoat() || !textures.has(mr.clearcoat_normal_texture)) return unperturbed;
    Vector3f side = dot(unperturbed, geometric) < 0 ? -geometric : geometric;
    return shading::keep_above_surface(
        shading::normal_mapped(mr.clearcoat_normal_texture, mr.clearcoat_normal_scale, unperturbed,
                               {a.tangent.x, a.tangent.y, a.tangent.z, a.tangent_w}, textures),
        side);
  }
};

struct SceneGouraudProgram {
  using Vertex = MeshVertex;
  struct Varyings {
    Point3f position;
    Vector3f normal;
    float u, v;
    Rgb lit;  // reflected light at the vertex, before the base texture
    float u1, v1;
  };
  InstanceUniforms uniforms;

  VertexOutput<Varyings> vertex(const MeshVertex& m) const {
    Point3f p = uniforms.world_point(m.position);
    Vector3f n = normalize(uniforms.world_normal(m.normal));
    Vector3f v = uniforms.view_direction(p);
    n = face_towards(n, v);
    SurfacePoint s = surface_point_untextured(*uniforms.material, m.color);
    if (uniforms.force_blinn && s.model == SurfaceModel::kPhong) {
      s.model = SurfaceModel::kBlinnPhong;
      s.lobe_normalization = shading::blinn_phong_lobe_normalization(s.shininess);
    }
    // Transmission: lit at the vertex, with the uniform surround seen through the glass.
    Rgb lit = s.model == SurfaceModel::kUnlit ? s.base
              : s.transmission > 0 && s.model == SurfaceModel::kMetallicRoughness
                  ? shade_transmissive(s, *uniforms.lights, uniforms.shadows, p, n, n, v,
                                       uniforms.lights->ambient)
                  : shade_surface(s, *uniforms.lights, uniforms.shadows, p, n, n, v);
    return {uniforms.clip_from_object(m.position), {p, n, m.uv.x, m.uv.y, lit, m.uv1.x, m.uv1.y}};
  }

  Rgb fragment(const Varyings& a, const Varyings& dx, const Varyings& dy, FragmentInfo info) const {
    const SurfaceMaterial& m = *uniforms.material;
    FragmentUvs uvs{{{a.u, a.v, dx.u, dx.v, dy.u, dy.v}, {a.u1, a.v1, dx.u1, dx.v1, dy.u1, dy.v1}}};
    const FragmentTextures textures(m.textures, m.filter, uvs);
    // Modulate, as fixed-function GL. (Lit at the vertices: normal maps do not apply.)
    Rgb c = a.lit * textures.color(m.base_texture);
    if (info.front_facing) c += shading::textured(m.emission, m.emission_texture, textures);
    return c * uniforms.exposure;
  }

  Vector3f normal(const Varyings& a) const {
    float i2 = dot(a.normal, a.normal);
    return i2 > 0 ? a.normal / std::sqrt(i2) : Vector3f();
  }
};

// One of the programs above for a material with alpha coverage: the same shading, plus the
// coverage the rasterizer tests (MASK) or blends with (BLEND), the vertex colour's alpha
// interpolated alongside. A separate type, so that opaque materials carry no extra varying.
template <class Inner>
struct WithCoverage {
  using Vertex = MeshVertex;
  struct Varyings {
    typename Inner::Varyings inner;
    float alpha;
  };
  Inner program;

  VertexOutput<Varyings> vertex(const MeshVertex& m) const {
    VertexOutput<typename Inner::Varyings> out = program.vertex(m);
    return {out.clip, {out.varyings, m.alpha}};
  }
  Rgb fragment(const Varyings& a, const Varyings& dx, const Varyings& dy, FragmentInfo info) const {
    return program.fragment(a.inner, dx.inner, dy.inner, info);
  }
  float coverage(const Varyings& a, const Varyings& dx, const Varyings& dy) const {
    const auto &i = a.inner, &x = dx.inner, &y = dy.inner;
    FragmentUvs uvs{{{i.u, i.v, x.u, x.v, y.u, y.v}, {i.u1, i.v1, x.u1, x.v1, y.u1, y.v1}}};
    return coverage_alpha(*program.uniforms.material, uvs, a.alpha);
  }
  Vector3f normal(const Varyings& a) const { return program.normal(a.inner); }
};

struct DepthCoverageProgram {
  using Vertex = MeshVertex;
  struct Varyings {
    float u, v, u1, v1, alpha;
  };
  Matrix4f clip_from_object;
  const SurfaceMaterial* material = nullptr;

  VertexOutput<Varyings> vertex(const MeshVertex& m) const {
    return {clip_from_object(m.position), {m.uv.x, m.uv.y, m.uv1.x, m.uv1.y, m.alpha}};
  }
  Rgb fragment(const Varyings&, FragmentInfo) const { return {}; }
  float coverage(const Varyings& a, const Varyings& dx, const Varyings& dy) const {
    FragmentUvs uvs{{{a.u, a.v, dx.u, dx.v, dy.u, dy.v}, {a.u1, a.v1, dx.u1, dx.v1, dy.u1, dy.v1}}};
    return coverage_alpha(*material, uvs, a.alpha);
  }
};

}  // namespace obscura::raster
