// Ghost paths through a lens system: how many there are (every pair of interfaces), that a
// sequence without reflections is the ordinary trace, that a reflection obeys the mirror
// equation, and that a ghost's throughput is the product of Fresnel reflectances computed here.
#include "obscura/camera/lens_ghosts.h"

#include <gtest/gtest.h>

#include <cmath>

#include "obscura/camera/builtin_lenses.h"

namespace obscura {
namespace {

double squared(double x) {
  return x * x;
}

TEST(LensGhosts, EveryPairOfInterfacesMakesOneGhost) {
  for (const char* name : {"double-gauss-50mm", "telephoto-250mm", "fisheye-10mm"}) {
    const auto lens = builtin_lens(name);
    // Interfaces counted from the table: where the medium's index changes (not the stop).
    int interfaces = 0;
    double before = 1;
    for (const LensSurface& s : lens->prescription().surfaces) {
      if (!s.is_stop && s.n_d != before) ++interfaces;
      before = s.n_d;
    }
    const std::vector<Ghost> ghosts = lens_ghosts(*lens);
    EXPECT_EQ(int(ghosts.size()), interfaces * (interfaces - 1) / 2) << name;
    for (const Ghost& g : ghosts) EXPECT_LT(g.second, g.first);
  }
}

TEST(LensGhosts, ASequenceWithoutReflectionsIsTheOrdinaryTrace) {
  const auto lens = builtin_lens("double-gauss-50mm");
  const LensRay ray{{3, -2, lens->front_z_mm() + 5},
                    Vector3d(-0.05, 0.03, -1) / length(Vector3d(-0.05, 0.03, -1))};
  TraceOptions unclipped;
  unclipped.apertures = false;
  auto expected = lens->trace(ray, TraceFrom::scene, unclipped);
  const std::vector<SurfaceVisit> path = direct_path(*lens);
  auto traced = lens->trace_sequence(ray, path, kWavelengthD_nm,
                                     StopGauge({lens->stop_radius_mm(), Aperture{}}));
  ASSERT_TRUE(expected && traced);
  EXPECT_NEAR(length(traced->ray.origin - expected->origin), 0, 1e-12);
  EXPECT_NEAR(length(traced->ray.direction - expected->direction), 0, 1e-12);
  EXPECT_LT(traced->aperture_gauge, 1);  // a ray well inside every opening
}

// A near-axial ray parallel to the axis, reflected by the convex front surface of radius R,
// leaves as if from the mirror's focus R / 2 behind the vertex.
TEST(LensGhosts, AReflectionObeysTheMirrorEquation) {
  const auto lens = builtin_lens("double-gauss-50mm");
  const double radius = lens->prescription().surfaces[0].radius_mm;
  ASSERT_GT(radius, 0);
  const double h = 1e-3;
  const LensRay ray{{0, h, lens->front_z_mm() + 10}, {0, 0, -1}};
  auto traced = lens->trace_sequence(ray, std::vector<SurfaceVisit>{{0, true}}, kWavelengthD_nm,
                                     StopGauge({lens->stop_radius_mm(), Aperture{}}));
  ASSERT_TRUE(traced);
  const LensRay& out = traced->ray;
  EXPECT_GT(out.direction.z, 0);  // back out towards the scene
  const double axis_z = out.origin.z - out.origin.y / out.direction.y * out.direction.z;
  EXPECT_NEAR(axis_z, lens->front_z_mm() - radius / 2, 1e-6 * radius);
}

// On the axis every surface is met at normal incidence: the ghost's throughput is R_i·R_j times
// (1 − R) for each pass, with R = ((n2 − n1) / (n2 + n1))² from the table's indices.
TEST(LensGhosts, AxialThroughputIsTheProductOfFresnelReflectances) {
  const auto lens = builtin_lens("double-gauss-50mm");
  const auto& surfaces = lens->prescription().surfaces;
  auto bare_r = [&](int i) {
    const double n1 = i == 0 ? 1 : surfaces[size_t(i) - 1].n_d, n2 = surfaces[size_t(i)].n_d;
    return squared((n2 - n1) / (n2 + n1));
  };
  const std::vector<Ghost> ghosts = lens_ghosts(*lens);
  for (const Ghost& g : {ghosts.front(), ghosts[ghosts.size() / 2], ghosts.back()}) {
    double expected = bare_r(g.first) * bare_r(g.second);
    // Passes: every surface once (the two that reflect too: the light crosses j on its way in
    // and i on its way out), plus twice more those between the two reflections.
    for (int k = 0; k < int(surfaces.size()); ++k) {
      const int passes = (k > g.second && k < g.first) ? 3 : 1;
      expected *= std::pow(1 - bare_r(k), passes);
    }
    EXPECT_NEAR(axial_ghost_throughput(*lens, g, LensCoating{}, kWavelengthD_nm), expected,
                1e-12 * expected)
        << g.first << "," << g.second;
    // A coating weakens every ghost.
    EXPECT_LT(axial_ghost_throughput(*lens, g, quarter_wave_coating(), 550),
              axial_ghost_throughput(*lens, g, LensCoating{}, 550));
  }
}

TEST(LensGhosts, APathVisitsItsSurfacesInOrder) {
  const auto lens = builtin_lens("double-gauss-50mm");
  const int count = int(lens->prescription().surfaces.size());
  const std::vector<SurfaceVisit> path = ghost_path(*lens, {5, 2});
  // 0…5, back 4…2, forwards 3…last: the surfaces between met three times.
  ASSERT_EQ(int(path.size()), 6 + 3 + (count - 3));
  EXPECT_TRUE(path[5].reflect);
  EXPECT_EQ(path[5].surface, 5);
  EXPECT_EQ(path[8].surface, 2);
  EXPECT_TRUE(path[8].reflect);
  EXPECT_EQ(path.back().surface, count - 1);
}

}  // namespace
}  // namespace obscura
