// Ghost flares of a lens-system camera (camera/lens_ghosts.h): the images its inter-reflections
// form of the scene's bright lights, added to the HDR film before glare (glare spreads whatever
// reaches the film, ghosts included) and before develop.
//
// Sources: point and spot lights (their intensity towards the camera), directional lights
// travelling towards the lens (their irradiance), and emissive objects (each a point at its
// emission-weighted centroid with the intensity Σ L·A·cos θ of its faces turned to the camera).
// Sources are not tested for occlusion: a light hidden behind geometry still flares.
//
// Each ghost of each source is a grid of rays over the part of the front element that reaches
// the sensor along the ghost's path (film/ray_grid_splat.h): a coarse grid finds that part, a
// fine one over it makes the image. A ray carries the power the source sends through its cell of
// the front plane (I·cos θ / r² per unit area, or E·cos θ for a directional light) times its
// path's throughput. On the sensor, irradiance E = Φ / area, and the film holds the
// radiance-equivalent E · 4N² / π (the camera equation the lens-system camera's ray weights
// follow, focused_lens_system.h) times the camera's exposure, like every other pixel.
//
// Colour: the rays are traced at three wavelengths (450, 550, 650 nm, each standing for its
// 100 nm band: the geometry disperses as the glasses do), and each band's throughput is spread
// over its band's colour by the spectral shape of the ghost's axial throughput (the coating's
// colour at normal incidence) through the CIE 1931 observer in linear Rec.709 (negative lobes
// clipped, as the glare does; each channel's weights sum to 1 over 400–700 nm, so a white light
// through a colourless path stays white).
//
// Deterministic: the rays are fixed grids and each pixel sums its grids in one order, for any
// thread count.
#pragma once

#include <atomic>
#include <string>
#include <vector>

#include "obscura/camera/camera.h"
#include "obscura/camera/lens_ghosts.h"
#include "obscura/color/rgb.h"
#include "obscura/film/image.h"
#include "obscura/scene/scene.h"

namespace obscura {

struct FlareSettings {
  int grid_cells = 40;    // per side of each ghost's fine ray grid, 4…1024
  int search_cells = 24;  // per side of the coarse grid that finds the ghost's rays, 4…1024
  // A ghost whose mean film value over its image (estimated from the coarse grid) stays below
  // this is skipped: 1e-5 is about a thirtieth of the first step of 8-bit sRGB (≈ 3e-4 linear),
  // invisible even three stops brighter.
  double min_film_value = 1e-5;
  // Set from another thread (a signal handler) to stop: the sources not yet traced are left out
  // and FlareStats::cancelled says so.
  const std::atomic<bool>* cancel = nullptr;
};

// The flare's cost bounds, checked before any ghost is traced (obscura::Error naming the lens's
// surfaces, the ghosts and the sources): a lens of N surfaces has up to N(N−1)/2 ghosts, each
// traced once per source along a path of about N surfaces, so the work is ghosts × sources × N.
// The double Gauss (11 surfaces, 45 ghosts) with 100 lights is about 50,000 and takes half a
// minute on two cores; the bound allows ten times that (1,000 such lights).
inline constexpr int kMaxFlareLensSurfaces = 64;  // ≤ 2,016 ghosts
inline constexpr long long kMaxFlareWork = 500'000;
// Throws obscura::Error naming the field when out of range.
void validate(const FlareSettings& settings);

// A bright light as the flare sees it, in world space.
struct FlareSource {
  std::string name;
  bool at_infinity = false;
  Point3d position;    // world, metres (not at infinity)
  Vector3d direction;  // at infinity: unit, the direction its light travels
  Rgb intensity;       // W/sr towards the camera; at infinity the irradiance, W/m²
};

// The scene's lights and emissive objects as flare sources for `camera` (at its shutter's
// middle); those that send it no light (behind it, a spot turned away, a face turned away) are
// left out.
std::vector<FlareSource> flare_sources(const Scene& scene, const Camera& camera);

struct FlareStats {
  int sources = 0;
  int ghosts_traced = 0;   // (source, ghost) pairs imaged
  int ghosts_skipped = 0;  // below min_film_value, or no ray reached the sensor
  double rays = 0;
  double seconds = 0;
  bool cancelled = false;  // stopped by FlareSettings::cancel before every source was traced
};

// The flare image (the camera's crop size, linear RGB in the film's units) of the sources
// through `camera`, which must be a lens-system camera (obscura::Error otherwise).
Image lens_flare_image(const std::vector<FlareSource>& sources, const Camera& camera,
                       const FlareSettings& settings = {}, FlareStats* stats = nullptr);
// The same for the scene's own sources.
Image lens_flare_image(const Scene& scene, const Camera& camera, const FlareSettings& settings = {},
                       FlareStats* stats = nullptr);

// Adds the flare image to channels 0–2 of a frame (the camera's crop size).
void add_lens_flare(Image& frame, const Image& flare);

// The image one path through the lens (a ghost's, or direct_path's: the source's focused image)
// forms of one source, as lens_flare_image computes it, skipping nothing: tests compare their
// energies. Channels R, G, B.
Image lens_path_image(const FlareSource& source, const Camera& camera,
                      const std::vector<SurfaceVisit>& path, const FlareSettings& settings = {});

}  // namespace obscura
