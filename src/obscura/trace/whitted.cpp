#include "obscura/trace/whitted.h"

#include <cmath>
#include <optional>
#include <vector>

namespace obscura {

namespace {

// A reflected or refracted ray and the share of its radiance that reaches the vertex it left.
struct Branch {
  Ray ray;
  Rgb weight;
};

// What one vertex of the ray tree gives by itself: emitted and directly lit light, and the
// specular rays it continues along (none, or one or two).
struct Vertex {
  Rgb L;
  int branch_count = 0;
  Branch branches[2];
};

// A vertex waiting for the radiance of its branches; the stack of these replaces recursion.
struct PendingVertex {
  Rgb L;       // this vertex's light plus the branches summed so far
  Rgb weight;  // of the branch being traced now
  int depth = 0;
  std::optional<Branch> second;  // the branch still to trace after the current one
  int second_budget = 0;         // rays its subtree may trace
};

Vertex shade(const TraceScene& scene, const Ray& ray, Sampler& sampler, RayCounts& counts,
             int depth, bool follow_specular, FirstHit* first_hit) {
  // Numbers for this vertex's light sample, drawn whether used or not (aligned dimensions).
  float u_select = sampler.next_1d();
  Point2f u_light = sampler.next_2d();

  depth == 0 ? ++counts.camera : ++counts.bounce;
  std::optional<SurfaceHit> hit = scene.intersect(ray);
  const LightSet& lights = scene.light_set();
  Vertex v;
  if (!hit) {
    const EnvironmentLight* env = lights.environment();
    if (env) v.L = env->radiance(ray.direction);
    return v;
  }
  if (depth == 0) record_first_hit(scene, *hit, ray.direction, first_hit);
  const TraceMaterial& material = scene.material(hit->material);
  Vector3f wo = -ray.direction;
  v.L = material.emitted_towards(*hit, wo);

  AnyBsdf bsdf = material.bsdf_at(*hit);
  Normal3f n = bsdf.is_transmissive() ? hit->shading_normal : reflection_normal(*hit, wo);
  ShadingFrame frame = ShadingFrame::from_normal(to_vector(n));
  bsdf.orient(frame);
  Vector3f wo_local = frame.to_local(wo);

  // 1. Direct light: one light sample and its shadow ray.
  if (!bsdf.is_delta() && !lights.empty()) {
    std::optional<LightSample> ls = lights.sample(hit->position, u_select, u_light);
    if (ls && ls->pdf > 0) {
      Vector3f wi_local = frame.to_local(ls->wi);
      Rgb f = bsdf.f(wo_local, wi_local) * std::abs(wi_local.z);
      if (!f.is_black() &&
          dot(hit->geometric_normal, wo) * dot(hit->geometric_normal, ls->wi) > 0) {
        Ray shadow = shadow_ray(scene, *hit, *ls);
        ++counts.shadow;
        if (!scene.occluded(shadow)) v.L += f * ls->radiance / ls->pdf;
      }
    }
  }

  // 2. Perfect specular surfaces: every delta lobe is a branch (reflection and refraction split
  //    deterministically by their weights, as Whitted did).
  if (bsdf.is_delta() && follow_specular) {
    // A delta BSDF picks its lobe from the 1D number: probe both sides of the Fresnel split.
    for (float u_lobe : {0.f, 0x1.fffffep-1f}) {
      std::optional<BsdfSample> bs = bsdf.sample(wo_local, u_lobe, {0.5f, 0.5f});
      if (!bs || bs->pdf <= 0) continue;
      // Weight = f·|cos|/pdf · (probability of the lobe), i.e. the lobe's full energy.
      Vector3f wi = normalize(frame.to_world(bs->wi));
      v.branches[v.branch_count++] = {spawn_ray(scene, *hit, wi), bs->f * std::abs(bs->wi.z)};
      if (bs->pdf >= 1) break;  // a single lobe (mirror, total internal reflection)
    }
  }
  // Reached a closed volume's boundary from inside: everything seen from here crossed its medium.
  if (material.absorbs_inside() && dot(hit->geometric_normal, wo) < 0) {
    Rgb kept = material.transmittance_inside(hit->t);
    v.L *= kept;
    for (int b = 0; b < v.branch_count; ++b) v.branches[b].weight *= kept;
  }
  return v;
}

}  // namespace

Rgb WhittedIntegrator::radiance(const TraceScene& scene, const Ray& camera_ray, Sampler& sampler,
                                RayCounts& counts, FirstHit* first_hit) const {
  // Depth-first, first branch before second, exactly as the recursive form visited the tree, so
  // the sampler's numbers and the sums' rounding are the same as before. Each subtree has a
  // budget of rays: a vertex spends one and splits the rest evenly between its branches (a single
  // branch keeps it all), so a camera ray traces at most kRayBudget rays, a full tree of depth 11
  // is traced whole, and chains (mirrors, total internal reflection) may run to kRayBudget deep.
  thread_local std::vector<PendingVertex> stack;
  stack.clear();
  Ray ray = camera_ray;
  ray.direction = normalize(camera_ray.direction);
  int depth = 0;
  int budget = kRayBudget;
  for (;;) {
    bool follow = depth < settings_.max_depth;
    Vertex v = shade(scene, ray, sampler, counts, depth, follow, depth == 0 ? first_hit : nullptr);
    int rest = budget - 1;
    int first_budget = v.branch_count == 2 ? (rest + 1) / 2 : rest;
    if (v.branch_count > 0 && first_budget > 0) {
      PendingVertex& parent = stack.emplace_back();
      parent.L = v.L;
      parent.weight = v.branches[0].weight;
      parent.depth = depth;
      if (v.branch_count == 2) {
        parent.second = v.branches[1];
        parent.second_budget = rest - first_budget;
      }
      ray = v.branches[0].ray;
      ++depth;
      budget = first_budget;
      continue;
    }
    // A leaf: hand its radiance up until a vertex has a branch left to trace.
    Rgb value = v.L;
    bool descended = false;
    while (!stack.empty()) {
      PendingVertex& parent = stack.back();
      parent.L += parent.weight * value;
      if (parent.second && parent.second_budget > 0) {
        parent.weight = parent.second->weight;
        ray = parent.second->ray;
        depth = parent.depth + 1;
        budget = parent.second_budget;
        parent.second.reset();
        descended = true;
        break;
      }
      value = parent.L;
      stack.pop_back();
    }
    if (!descended) return value;
  }
}

}  // namespace obscura
