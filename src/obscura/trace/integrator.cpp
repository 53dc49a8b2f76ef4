#include "obscura/trace/integrator.h"

#include "obscura/math/error.h"

namespace obscura {

Rgb Integrator::spectral_radiance(const TraceScene&, const Ray&, SampledWavelengths&, Sampler&,
                                  RayCounts&, FirstHit*) const {
  throw Error("spectral rendering", "only the path tracer renders spectrally");
}

void record_first_hit(const TraceScene& scene, const SurfaceHit& hit, Vector3f direction,
                      FirstHit* first_hit) {
  if (!first_hit) return;
  first_hit->hit = true;
  first_hit->albedo = scene.material(hit.material).bsdf_at(hit).albedo();
  first_hit->normal = reflection_normal(hit, normalize(-direction));
  first_hit->position = hit.position;
  first_hit->range = hit.t * length(direction);
  first_hit->id = hit.mesh;
}

}  // namespace obscura
