// Built-in programs (vertex + fragment shader pairs) over world-space meshes.
//
// All take MeshVertex input and a clip_from_world matrix (the camera's projection · view).
// Lighting happens in world space with the eye at `eye`. Colours are linear RGB.
//   UnlitProgram        vertex colour × base colour, no lighting
//   FlatProgram         Phong model once per face (face normal, face centre)
//   GouraudProgram      Phong model at the vertices, colours interpolated
//   PhongProgram<M>     Phong (M = kPhong) or Blinn-Phong (kBlinnPhong) model per pixel
//   TexturedProgram     per-pixel Blinn-Phong with a diffuse texture (nearest, bilinear,
//                       trilinear); unlit when the light set is empty and ambient is 1
#pragma once

#include <span>

#include "obscura/raster/clip_transform.h"
#include "obscura/raster/lights.h"
#include "obscura/raster/phong.h"
#include "obscura/raster/texture.h"
#include "obscura/raster/varyings.h"

namespace obscura::raster {

struct MeshVertex {
  Point3f position;    // world space
  Vector3f normal;     // world space, unit length
  Point2f uv;          // texture coordinates (glTF convention)
  Rgb color{1, 1, 1};  // vertex colour, multiplies the material's colours
  float alpha = 1;     // vertex colour alpha, multiplies the material's coverage
  Point2f uv1;         // the second texture coordinate set (glTF TEXCOORD_1)
  Vector4f tangent;    // xyz along +u, w = ±1 handedness (glTF); zero where no normal map uses it
};

struct SceneUniforms {
  Matrix4f clip_from_world;
  Point3f eye;  // world-space camera position, for specular highlights
  const LightSet* lights = nullptr;
};

struct UnlitProgram {
  using Vertex = MeshVertex;
  struct Varyings {
    Rgb color;
  };
  SceneUniforms scene;
  Rgb base_color{1, 1, 1};

  VertexOutput<Varyings> vertex(const MeshVertex& v) const {
    return {scene.clip_from_world(v.position), {v.color * base_color}};
  }
  Rgb fragment(const Varyings& v, FragmentInfo) const { return v.color; }
};

struct GouraudProgram {
  using Vertex = MeshVertex;
  struct Varyings {
    Rgb color;
  };
  SceneUniforms scene;
  PhongMaterial material;

  VertexOutput<Varyings> vertex(const MeshVertex& v) const {
    PhongMaterial m = material;
    m.ambient *= v.color, m.diffuse *= v.color;
    Rgb c = shade_phong<SpecularModel::kPhong>(m, *scene.lights, v.position, v.normal,
                                               normalize(scene.eye - v.position));
    return {scene.clip_from_world(v.position), {c}};
  }
  Rgb fragment(const Varyings& v, FragmentInfo) const { return v.color; }
};

template <SpecularModel M>
struct PhongProgram {
  using Vertex = MeshVertex;
  struct Varyings {
    Point3f position;
    Vector3f normal;
    Rgb color;
  };
  SceneUniforms scene;
  PhongMaterial material;

  VertexOutput<Varyings> vertex(const MeshVertex& v) const {
    return {scene.clip_from_world(v.position), {v.position, v.normal, v.color}};
  }
  Rgb fragment(const Varyings& v, FragmentInfo) const {
    PhongMaterial m = material;
    m.ambient *= v.color, m.diffuse *= v.color;
    return shade_phong<M>(m, *scene.lights, v.position, normalize(v.normal),
                          normalize(scene.eye - v.position));
  }
  Vector3f normal(const Varyings& v) const { return normalize(v.normal); }
};

// One colour per face: the face normal (from `face_normals`, indexed by primitive) and the
// model evaluated at the face's centre (`face_centers`).
struct FlatProgram {
  using Vertex = MeshVertex;
  struct Varyings {
    Rgb color;
  };
  SceneUniforms scene;
  PhongMaterial material;
  std::span<const Vector3f> face_normals;
  std::span<const Point3f> face_centers;

  VertexOutput<Varyings> vertex(const MeshVertex& v) const {
    return {scene.clip_from_world(v.position), {v.color}};
  }
  Rgb fragment(const Varyings&, FragmentInfo f) const {
    Point3f c = face_centers[f.primitive];
    return shade_phong<SpecularModel::kPhong>(material, *scene.lights, c, face_normals[f.primitive],
                                              normalize(scene.eye - c));
  }
  Vector3f normal(const Varyings&) const { return {}; }  // not known per fragment here
};

struct TexturedProgram {
  using Vertex = MeshVertex;
  struct Varyings {
    Point3f position;
    Vector3f normal;
    float u, v;
  };
  SceneUniforms scene;
  PhongMaterial material;  // diffuse and ambient are multiplied by the texture
  const Texture* texture = nullptr;
  TextureFilter filter = TextureFilter::kTrilinear;

  VertexOutput<Varyings> vertex(const MeshVertex& v) const {
    return {scene.clip_from_world(v.position), {v.position, v.normal, v.uv.x, v.uv.y}};
  }
  Rgb fragment(const Varyings& v, const Varyings& d_dx, const Varyings& d_dy, FragmentInfo) const {
    Rgb t = texture->sample(filter, v.u, v.v, d_dx.u, d_dx.v, d_dy.u, d_dy.v);
    PhongMaterial m = material;
    m.ambient *= t, m.diffuse *= t;
    return shade_phong<SpecularModel::kBlinnPhong>(
        m, *scene.lights, v.position, normalize(v.normal), normalize(scene.eye - v.position));
  }
  Vector3f normal(const Varyings& v) const { return normalize(v.normal); }
};

}  // namespace obscura::raster
