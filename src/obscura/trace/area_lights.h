// Emissive triangles as area lights, chosen in proportion to their power (area × luminance of
// emitted radiance; for a textured emitter, of the texture's mean over the triangle), then sampled
// from the shaded point: uniformly in the solid angle the triangle subtends (a spherical triangle,
// math/spherical_triangle.h) where area sampling's d²/cos would vary much across the triangle,
// uniformly by area otherwise. The choice depends only on the point and the triangle, so pdf()
// reproduces it for multiple importance sampling.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "obscura/color/blackbody_spectrum.h"
#include "obscura/color/rgb.h"
#include "obscura/math/spherical_triangle.h"
#include "obscura/math/vector.h"
#include "obscura/scene/scene.h"
#include "obscura/scene/texture.h"

namespace obscura {

enum class AreaLightSampling {
  kSolidAngle,  // spherical triangles where they are well conditioned, area elsewhere
  kArea,        // always uniform by area (the density in solid angle varies as d²/cos)
};

struct AreaLightPoint {
  Point3f position;
  Normal3f normal;  // the emitting side
  Rgb radiance;     // emitted towards the front side
  float pdf_area;   // density with respect to surface area over all lights (m⁻²)
  const BlackbodySpectrum* spectrum = nullptr;  // a blackbody emitter's shape, else null
};

struct AreaLightSample {
  Vector3f wi;     // unit, from the shaded point towards the light
  float distance;  // to the light point
  Point3f position;
  Normal3f normal;  // the emitting side
  Rgb radiance;     // arriving along −wi
  float pdf;        // solid-angle density over all area lights (sr⁻¹)
  // For spectral mode: a blackbody emitter's spectral shape (radiance is then its RGB
  // equivalent); null for an emitter whose spectrum is its RGB colour lifted.
  const BlackbodySpectrum* spectrum = nullptr;
};

class AreaLights {
 public:
  // When spherical sampling is used. Area sampling's density in solid angle is ∝ 1/J with
  // J = cos/d²; where J varies by at most a factor r over the triangle (a bound, see
  // spherical()), area sampling's variance is at most (1 + r)²/4r times that of uniform
  // solid-angle sampling (Kantorovich's inequality): 1.56 for r = 4, about what the spherical
  // construction's extra cost per sample is worth. (On the reference Cornell box r = 2, 4 and
  // 8 cost 15, 11 and 7 % more time than area sampling for 1.5, 1.1 and 0.9 % less error.)
  static constexpr float kMinJacobianRatio = 4;
  static constexpr double kMinSphericalSolidAngle = 3e-4;
  static constexpr double kMaxSphericalSolidAngle = 6.2;

  AreaLights() = default;
  // `meshes` in world space, indexed as the ids hits report (SurfaceHit::mesh); meshes whose
  // material does not emit (or that are empty) are not lights. A material's emission texture is
  // looked up in `textures` (which must outlive this) at the mesh's UVs.
  AreaLights(const std::vector<Mesh>& meshes, const std::vector<Material>& materials,
             AreaLightSampling sampling = AreaLightSampling::kSolidAngle,
             const std::vector<Texture>* textures = nullptr);

  bool empty() const { return triangles_.empty(); }
  size_t size() const { return triangles_.size(); }
  AreaLightSampling sampling() const { return sampling_; }

  // A light point for shading point `p`: `u_select` picks a triangle, `u_point` a point on it.
  // Nothing when the chosen triangle faces away from `p` (lights emit from their front face).
  std::optional<AreaLightSample> sample(Point3f p, float u_select, Point2f u_point) const;
  // The solid-angle density with which sample() from `p` gives `light_point` on triangle
  // `primitive` of mesh `mesh` (0 for a triangle that is not a light or faces away): what
  // multiple importance sampling weighs a BSDF sample that hit the light against.
  float pdf(Point3f p, uint32_t mesh, uint32_t primitive, Point3f light_point) const;

  // A point uniform by area, independent of any shading point (the `direct` integrator).
  AreaLightPoint sample_point(float u_select, Point2f u_point) const;
  // The area density with which sample_point() picks points on triangle `primitive` of `mesh`.
  float pdf_area(uint32_t mesh, uint32_t primitive) const;
  // Σ area · π · luminance(radiance): the emitted power's luminance (W), for light selection.
  double power() const { return power_; }

 private:
  struct Triangle {
    Point3f p0, p1, p2, centroid;
    Normal3f normal;
    Rgb radiance;  // the emission factor; times the texture where there is one
    float area = 0;
    int32_t spectrum = -1;  // index into spectra_ for a blackbody emitter
    const Texture* texture = nullptr;
    UvTransform transform;  // the emission texture's
    Point2f uv0, uv1, uv2;
  };
  // Emitted radiance at barycentric b (b.x towards p1, b.y towards p2).
  static Rgb radiance_at(const Triangle& tri, Point2f b);
  // Barycentrics of a point in the triangle's plane.
  static Point2f barycentric(const Triangle& tri, Point3f q);
  int32_t index_of(uint32_t mesh, uint32_t primitive) const;
  float selection_probability(size_t i) const { return cdf_[i] - (i == 0 ? 0.f : cdf_[i - 1]); }
  // The triangle as seen from p when spherical sampling applies to it there.
  std::optional<SphericalTriangle> spherical(const Triangle& tri, Point3f p) const;

  std::vector<Triangle> triangles_;
  std::vector<BlackbodySpectrum> spectra_;  // one per blackbody-emitting mesh
  const BlackbodySpectrum* spectrum_of(const Triangle& tri) const {
    return tri.spectrum < 0 ? nullptr : &spectra_[tri.spectrum];
  }
  std::vector<float> cdf_;  // cumulative selection probability, cdf_.back() == 1
  // Per mesh, per triangle: its index in triangles_, or −1; empty for meshes that do not emit.
  std::vector<std::vector<int32_t>> light_of_triangle_;
  double power_ = 0;
  AreaLightSampling sampling_ = AreaLightSampling::kSolidAngle;
};

}  // namespace obscura
