// Smooth-shaded meshes at their silhouettes (issue: a dark one-pixel rim that Blender Cycles does
// not show). In a white furnace, a convex mesh whose faces are white Lambertian reflectors lets
// every direction above a face's plane escape to the environment, so a pixel's expected value is
// the fraction of its shading normal's cosine lobe that lies above that plane: (1 + cos θ) / 2
// for a tilt θ between the shading normal used and the face normal (the lobe projects onto the
// unit disk; the plane cuts out the half-ellipse of axes 1 and cos θ). Any rule that keeps the
// lobe on the viewer's side of the face stays near 1; the old rule, which turned a normal
// pointing away from the viewer around to face it, put the lobe inside the sphere (≈ 0.78 at the
// rim of this sphere).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "obscura/math/sampler.h"
#include "obscura/trace/path_tracer.h"
#include "trace_test_scenes.h"

namespace obscura {
namespace {

TEST(Silhouette, SmoothSphereInAWhiteFurnaceHasNoDarkRim) {
  // A coarse sphere (6 rings × 12 segments) with the exact sphere normals at its vertices: the
  // interpolated normals tilt up to ≈ 22° from the faces, far more than a finely tessellated
  // model's, so the silhouette effect is large and easy to see.
  Scene scene;
  scene.materials = {diffuse_material("white", Rgb(1.f))};
  Mesh sphere = testing::make_sphere({0, 0, 0}, 1, 0, 6, 12);
  for (Point3f p : sphere.positions) sphere.normals.push_back(Normal3f(normalize(to_vector(p))));
  scene.add_meshes({sphere});
  Camera camera = testing::make_camera({0, 0, 4}, {0, 0, 0}, 48, 36);
  scene.camera = camera;
  TraceScene trace(scene, testing::embree_device());
  trace.set_environment(EnvironmentLight(Rgb(1.f)));
  PathTracer tracer(PathTracerSettings{});

  // The largest tilt between a vertex normal and the face around it bounds the loss inside the
  // silhouette: (1 + cos θ) / 2.
  double worst_cos = 1;
  for (size_t t = 0; t < sphere.indices.size(); t += 3) {
    Point3f a = sphere.positions[sphere.indices[t]], b = sphere.positions[sphere.indices[t + 1]],
            c = sphere.positions[sphere.indices[t + 2]];
    Vector3f face = normalize(cross(b - a, c - a));
    for (int k = 0; k < 3; ++k)
      worst_cos = std::min(
          worst_cos, double(std::abs(dot(face, to_vector(sphere.normals[sphere.indices[t + k]])))));
  }
  const double interior_bound = (1 + worst_cos) / 2;
  ASSERT_GT(interior_bound, 0.95);

  RayCounts counts;
  const int spp = 256;
  double darkest = 2, rim_object_sum = 0;
  int rim_pixels = 0, rim_object_samples = 0;
  for (int y = 0; y < camera.film.height_px; ++y)
    for (int x = 0; x < camera.film.width_px; ++x) {
      double sum = 0, object_sum = 0;
      int object_samples = 0;
      for (int s = 0; s < spp; ++s) {
        Sampler sampler(SamplerType::kIndependent, 3, {x, y}, uint32_t(s));
        Point2f u = sampler.next_2d();
        sampler.next_2d(), sampler.next_1d();  // lens and time, unused
        Ray ray = camera.generate_ray({x + u.x, y + u.y})->to_ray();
        FirstHit first;
        double L = tracer.radiance(trace, ray, sampler, counts, &first).g;
        sum += L;
        if (first.hit) object_sum += L, ++object_samples;
      }
      double mean = sum / spp;
      darkest = std::min(darkest, mean);
      // Pixels the silhouette crosses (partly object, partly background): their object samples.
      if (object_samples > 0 && object_samples < spp) {
        rim_object_sum += object_sum, rim_object_samples += object_samples, ++rim_pixels;
      }
    }
  ASSERT_GT(rim_pixels, 40);
  // Noise: a pixel's mean over 256 samples has a standard error below 0.02 here.
  EXPECT_GT(darkest, interior_bound - 0.06) << "a pixel darker than the furnace allows";
  // The sphere seen exactly at its silhouette, averaged over ~2·10⁴ samples (standard error
  // < 0.002): 0.986 with the rule of math/shading_normal.h, 0.942 with the old one.
  EXPECT_GT(rim_object_sum / rim_object_samples, interior_bound - 0.005)
      << "the silhouette is darker on average";
}

}  // namespace
}  // namespace obscura
