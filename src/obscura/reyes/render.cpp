#include "obscura/reyes/render.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <memory>
#include <mutex>
#include <string>
#include <unordered_map>

#include "obscura/camera/camera_sample.h"
#include "obscura/camera/pixel_filter.h"
#include "obscura/film/aov_buffers.h"
#include "obscura/film/film.h"
#include "obscura/film/pass_schedule.h"
#include "obscura/math/error.h"
#include "obscura/reyes/dicing.h"
#include "obscura/reyes/grid.h"
#include "obscura/reyes/hider.h"
#include "obscura/reyes/sphere_patches.h"

namespace obscura::reyes {

namespace {

// What splitting produced: the lattice plans (triangles' and sphere patches') and their blocks,
// in a fixed order.
struct Split {
  std::vector<DicePlan> plans;
  std::vector<SphereFrame> spheres;
  std::vector<PatchPlan> patches;
  std::vector<Block> blocks;  // Block::sphere: `plan` indexes `patches`, else `plans`
  uint64_t pieces = 0, eye_splits = 0, eye_split_culled = 0;
};

// The analytic sphere an instance draws, if REYES dices it natively (a rigid mesh that keeps
// one).
const AnalyticSphere* analytic_sphere(const Scene& scene, uint32_t instance) {
  const Mesh& mesh = scene.meshes[scene.instances[instance].mesh];
  return mesh.analytic_sphere && !mesh.deforms() ? &*mesh.analytic_sphere : nullptr;
}

SphereFrame sphere_frame(const ReyesScene& scene, const FrameView& view, uint32_t instance,
                         const AnalyticSphere& sphere) {
  const SurfaceMotion& motion = scene.motion();
  const Transform open = motion.world_from_object(instance, view.open_s());
  const Transform close = view.moves() ? motion.world_from_object(instance, view.close_s()) : open;
  const Displacement& d =
      scene.displacement(scene.scene().material_of(scene.scene().instances[instance]));
  return {.instance = instance,
          .center = {sphere.center.x, sphere.center.y, sphere.center.z},
          .radius = sphere.radius,
          .camera_from_object_open = view.camera_from_world_open() * open,
          .camera_from_object_close = view.camera_from_world_close() * close,
          .displacement = d.any() ? &d : nullptr,
          .reach = d.any() ? std::max(d.bound, d.largest) : 0.0};
}

// The frame's warnings about displacement: beyond its bound (naming the materials whose
// displacement can exceed theirs), or on surfaces REYES does not displace.
void warn_about_displacement(const ReyesScene& scene, uint64_t overruns,
                             std::vector<std::string>& warnings) {
  const Scene& s = scene.scene();
  std::string beyond, undisplaced;
  for (uint32_t m = 0; m < s.materials.size(); ++m) {
    const Displacement& d = scene.displacement(m);
    if (!(d.any() && d.largest > d.bound)) continue;
    if (!beyond.empty()) beyond += ", ";
    beyond += "'";
    beyond += s.materials[m].name;
    beyond += "'";
  }
  for (uint32_t i = 0; i < s.instances.size(); ++i)
    if (scene.displacement(s.material_of(s.instances[i])).any() && !analytic_sphere(s, i)) {
      undisplaced = s.instances[i].name;
      break;
    }
  if (overruns > 0) {
    std::string w = "reyes: the displacement of material ";
    w += beyond;
    w += " reached beyond its displacement_bound at " + std::to_string(overruns);
    w += " vertices; the bounds were grown to the real displacement (raise displacement_bound)";
    warnings.push_back(w);
  }
  if (!undisplaced.empty()) {
    std::string w = "reyes: displacement applies to analytic spheres only; '";
    w += undisplaced;
    w += "' (a triangle mesh) is drawn undisplaced";
    warnings.push_back(w);
  }
}

LatticePoint corner(const Transform& open, const Transform& close, Point3d world_open,
                    Point3d world_close, Point2d bary) {
  return {open(world_open), close(world_close), bary};
}

// Splits the triangles [first, end) of one instance.
void split_triangles(const ReyesScene& scene, const FrameView& view, uint32_t instance,
                     uint32_t first, uint32_t end, const DiceLimits& limits, int eye_split_limit,
                     const RasterBounds& region, double margin_px, Split& out) {
  const SurfaceMotion& motion = scene.motion();
  struct Pending {
    Piece piece;
    int eye_level = 0, size_level = 0;
  };
  std::vector<Pending> stack;
  auto push_split = [&](const Piece& p, int eye_level, int size_level) {
    // Pushed in reverse so that the pieces are planned in split order.
    const std::array<Piece, 4> children = split_in_four(p);
    for (auto c = children.rbegin(); c != children.rend(); ++c)
      stack.push_back({*c, eye_level, size_level});
  };
  for (uint32_t t = first; t < end; ++t) {
    const auto w0 = motion.world_triangle(instance, t, view.open_s());
    const auto w1 = view.moves() ? motion.world_triangle(instance, t, view.close_s()) : w0;
    Piece piece{instance, t, {}};
    static constexpr Point2d kBary[3] = {{0, 0}, {1, 0}, {0, 1}};
    for (int k = 0; k < 3; ++k)
      piece.corners[size_t(k)] =
          corner(view.camera_from_world_open(), view.camera_from_world_close(), w0[size_t(k)],
                 w1[size_t(k)], kBary[k]);
    stack.push_back({piece, 0, 0});
    while (!stack.empty()) {
      const Pending next = stack.back();
      stack.pop_back();
      const Piece& p = next.piece;
      switch (eye_verdict(view, p, margin_px)) {
        case EyeVerdict::kBehind:
        case EyeVerdict::kOutside:
          continue;
        case EyeVerdict::kStraddles:
          if (next.eye_level >= eye_split_limit) {
            ++out.eye_split_culled;
            continue;
          }
          ++out.eye_splits;
          push_split(p, next.eye_level + 1, next.size_level);
          continue;
        case EyeVerdict::kInFront:
          break;
      }
      if (!piece_bounds(view, p).overlaps(region)) continue;
      const DicePlan plan = plan_dicing(view, p, limits);
      if (plan.too_large() && next.size_level < kMaxSizeSplits) {
        push_split(p, next.eye_level, next.size_level + 1);
        continue;
      }
      ++out.pieces;
      const size_t before = out.blocks.size();
      cut_blocks(view, plan, uint32_t(out.plans.size()), limits, out.blocks);
      // Blocks that cannot reach the film's region are dropped before anything is diced.
      out.blocks.erase(std::remove_if(out.blocks.begin() + long(before), out.blocks.end(),
                                      [&](const Block& b) { return !b.bounds.overlaps(region); }),
                       out.blocks.end());
      if (out.blocks.size() > before) out.plans.push_back(plan);
    }
  }
}

Split split_scene(const ReyesScene& scene, const FrameView& view, const DiceLimits& limits,
                  int eye_split_limit, const RasterBounds& region, double margin_px) {
  // Chunks of triangles split in parallel, joined in order: the same plans and blocks, in the
  // same order, on any number of threads.
  // An analytic sphere is one chunk of its own (its patches are planned together).
  struct Chunk {
    uint32_t instance, first, end;
    const AnalyticSphere* sphere;
  };
  constexpr uint32_t kChunk = 512;
  std::vector<Chunk> chunks;
  const Scene& s = scene.scene();
  for (uint32_t i = 0; i < s.instances.size(); ++i) {
    if (const AnalyticSphere* sphere = analytic_sphere(s, i)) {
      chunks.push_back({i, 0, 0, sphere});
      continue;
    }
    const uint32_t triangles = uint32_t(s.meshes[s.instances[i].mesh].triangle_count());
    for (uint32_t t = 0; t < triangles; t += kChunk)
      chunks.push_back({i, t, std::min(triangles, t + kChunk), nullptr});
  }
  std::vector<Split> parts(chunks.size());
  tbb::parallel_for(size_t(0), chunks.size(), [&](size_t c) {
    const Chunk& chunk = chunks[c];
    if (!chunk.sphere) {
      split_triangles(scene, view, chunk.instance, chunk.first, chunk.end, limits, eye_split_limit,
                      region, margin_px, parts[c]);
      return;
    }
    Split& part = parts[c];
    part.spheres.push_back(sphere_frame(scene, view, chunk.instance, *chunk.sphere));
    PatchSplit patches;
    split_sphere(view, part.spheres[0], 0, limits, eye_split_limit, region, margin_px, patches);
    part.patches = std::move(patches.plans);
    part.blocks = std::move(patches.blocks);
    part.pieces = patches.pieces;
    part.eye_splits = patches.eye_splits;
    part.eye_split_culled = patches.eye_split_culled;
  });
  Split all;
  for (Split& part : parts) {
    const uint32_t offset = uint32_t(all.plans.size());
    const uint32_t patch_offset = uint32_t(all.patches.size());
    const uint32_t sphere_offset = uint32_t(all.spheres.size());
    for (Block& b : part.blocks) b.plan += b.sphere ? patch_offset : offset;
    for (PatchPlan& p : part.patches) p.sphere += sphere_offset;
    all.plans.insert(all.plans.end(), part.plans.begin(), part.plans.end());
    all.spheres.insert(all.spheres.end(), part.spheres.begin(), part.spheres.end());
    all.patches.insert(all.patches.end(), part.patches.begin(), part.patches.end());
    all.blocks.insert(all.blocks.end(), part.blocks.begin(), part.blocks.end());
    all.pieces += part.pieces;
    all.eye_splits += part.eye_splits;
    all.eye_split_culled += part.eye_split_culled;
  }
  return all;
}

// A block's grid while buckets that need it are unfinished.
struct GridSlot {
  std::mutex mutex;
  std::shared_ptr<const Grid> grid;
  std::atomic<int> users{0};
};

}  // namespace

ReyesStats render(const ReyesScene& scene, const Camera& camera, const ReyesSettings& settings,
                  Film& film, AovBuffers* aovs, const ProgressCallback& progress,
                  std::vector<SeenTriangle>* seen) {
  validate(settings);
  const Bounds2i crop = camera.film.crop_pixels();
  if (film.width() != crop.width() || film.height() != crop.height())
    throw Error("render", "the film (" + std::to_string(film.width()) + "x" +
                              std::to_string(film.height()) + ") must match the camera's crop (" +
                              std::to_string(crop.width()) + "x" + std::to_string(crop.height()) +
                              ")");
  const FrameView view(camera, scene.moves());
  const PreparedCamera prepared = camera.prepare();
  const CameraSampleOrder order(camera, scene.moves(), false);
  const auto exposure = float(camera.exposure_scale());
  const Vignetting& vignetting = camera.lens.vignetting;
  const bool needs_rays =
      scene.scene().environment.has_value() || vignetting.natural || vignetting.mechanical();
  // How far a sample strays outside its pixel (the filter's radius beyond half a pixel).
  const double margin_px = std::max(0.0, filter_radius_px(camera.film.filter) - 0.5) + 1e-6;

  // REYES tells no albedo: its AOVs are the rasterizer's (normal, depth, range, id).
  if (aovs && aovs->has_albedo()) *aovs = AovBuffers(film.width(), film.height(), false);
  if (seen) seen->assign(size_t(film.width()) * size_t(film.height()), SeenTriangle{});
  ReyesStats stats;
  PassSchedule passes(
      1, 1, OnCancel::kAbandonPass,
      {.time_limit_s = settings.time_limit_s, .cancel = settings.cancel, .share = &settings.share});

  // Buckets: the owned tiles of the work share, each cut into buckets.
  std::vector<Bounds2i> buckets;
  std::vector<Bounds2i> tiles = make_tiles(film.bounds(), kTileSize);
  std::vector<int> tile_first(tiles.size(), -1);
  for (size_t t = 0; t < tiles.size(); ++t) {
    if (!settings.share.owns_tile(int(t))) continue;
    tile_first[t] = int(buckets.size());
    for (const Bounds2i& b : make_tiles(tiles[t], settings.bucket_size)) buckets.push_back(b);
  }
  const int tile_columns = (film.width() + kTileSize - 1) / kTileSize;

  // Split everything that can reach the crop (grown by the samples' margin).
  RasterBounds region;
  region.add(crop.min.x, crop.min.y);
  region.add(crop.max.x, crop.max.y);
  region.grow(margin_px + 1);
  const DiceLimits limits{.side_px = std::sqrt(settings.shading_rate),
                          .grid_size = settings.grid_size};
  const Split split = split_scene(scene, view, limits, settings.eye_splits, region, margin_px);
  stats.pieces = split.pieces;
  stats.eye_splits = split.eye_splits;
  stats.eye_split_culled = split.eye_split_culled;
  if (split.eye_split_culled > 0)
    stats.warnings.push_back("reyes: " + std::to_string(split.eye_split_culled) +
                             " pieces still crossed the near plane after " +
                             std::to_string(settings.eye_splits) +
                             " eye splits and were dropped (--reyes-eye-splits)");

  // Which blocks each bucket samples.
  std::vector<std::vector<uint32_t>> lists(buckets.size());
  std::vector<GridSlot> slots(split.blocks.size());
  for (uint32_t k = 0; k < split.blocks.size(); ++k) {
    RasterBounds b = split.blocks[k].bounds;
    b.grow(margin_px);
    const int fx0 = std::max(0, int(std::floor(b.x0)) - crop.min.x);
    const int fx1 = std::min(film.width() - 1, int(std::floor(b.x1)) - crop.min.x);
    const int fy0 = std::max(0, int(std::floor(b.y0)) - crop.min.y);
    const int fy1 = std::min(film.height() - 1, int(std::floor(b.y1)) - crop.min.y);
    if (fx0 > fx1 || fy0 > fy1) continue;
    for (int ty = fy0 / kTileSize; ty <= fy1 / kTileSize; ++ty)
      for (int tx = fx0 / kTileSize; tx <= fx1 / kTileSize; ++tx) {
        const size_t t = size_t(ty) * size_t(tile_columns) + size_t(tx);
        if (tile_first[t] < 0) continue;
        const Bounds2i& tile = tiles[t];
        const int bx0 = (std::max(fx0, tile.min.x) - tile.min.x) / settings.bucket_size;
        const int bx1 = (std::min(fx1, tile.max.x - 1) - tile.min.x) / settings.bucket_size;
        const int by0 = (std::max(fy0, tile.min.y) - tile.min.y) / settings.bucket_size;
        const int by1 = (std::min(fy1, tile.max.y - 1) - tile.min.y) / settings.bucket_size;
        const int columns = (tile.width() + settings.bucket_size - 1) / settings.bucket_size;
        for (int by = by0; by <= by1; ++by)
          for (int bx = bx0; bx <= bx1; ++bx) {
            lists[size_t(tile_first[t] + by * columns + bx)].push_back(k);
            ++slots[k].users;
          }
      }
  }

  // Nearest first, so that occlusion culling finds the near surfaces before what they hide; the
  // order is global (depth, then block), so ties resolve alike in every bucket.
  tbb::parallel_for(size_t(0), lists.size(), [&](size_t b) {
    std::sort(lists[b].begin(), lists[b].end(), [&](uint32_t x, uint32_t y) {
      const double dx = split.blocks[x].depth_min, dy = split.blocks[y].depth_min;
      return dx != dy ? dx < dy : x < y;
    });
  });

  std::unordered_map<long long, size_t> bucket_index;
  for (size_t b = 0; b < buckets.size(); ++b)
    bucket_index[(long long)buckets[b].min.y * (1LL << 32) + buckets[b].min.x] = b;

  std::mutex stats_mutex;
  GridCounts grid_counts;
  HiderCounts hider_counts;
  std::atomic<uint64_t> live_grids{0}, live_bytes{0};
  const int bucket_count = int(buckets.size());
  Pass pass;
  while (passes.next(pass)) {
    for_each_tile_parallel(
        buckets,
        [&](const Bounds2i& bucket) {
          if (passes.cancel_requested()) return;
          const size_t b = bucket_index.at((long long)bucket.min.y * (1LL << 32) + bucket.min.x);
          BucketHider hider(view, order, settings, bucket, crop.min);
          GridCounts diced;
          HiderCounts sampled;
          uint64_t culled = 0;
          auto release = [&](GridSlot& slot) {
            if (--slot.users > 0) return;
            std::lock_guard lock(slot.mutex);
            if (!slot.grid) return;
            --live_grids;
            live_bytes -= slot.grid->bytes();
            slot.grid.reset();
          };
          for (uint32_t k : lists[b]) {
            GridSlot& slot = slots[k];
            if (hider.hides(split.blocks[k].depth_min)) {
              ++culled;
              release(slot);
              continue;
            }
            std::shared_ptr<const Grid> grid;
            {
              std::lock_guard lock(slot.mutex);
              if (!slot.grid) {
                const Block& block = split.blocks[k];
                if (block.sphere) {
                  const PatchPlan& patch = split.patches[block.plan];
                  slot.grid = std::make_shared<const Grid>(dice_and_shade_patch(
                      scene, view, split.spheres[patch.sphere], patch, block, k, diced));
                } else {
                  slot.grid = std::make_shared<const Grid>(
                      dice_and_shade(scene, view, split.plans[block.plan], block, k, diced));
                }
                const uint64_t live = ++live_grids;
                const uint64_t bytes = live_bytes += slot.grid->bytes();
                std::lock_guard stats_lock(stats_mutex);
                stats.peak_grids = std::max(stats.peak_grids, live);
                stats.peak_grid_bytes = std::max(stats.peak_grid_bytes, bytes);
              }
              grid = slot.grid;
            }
            hider.sample(*grid, sampled);
            release(slot);
          }
          hider.resolve(scene, prepared, needs_rays, exposure, film, aovs, seen);
          std::lock_guard lock(stats_mutex);
          grid_counts.add(diced);
          hider_counts.tested += sampled.tested;
          hider_counts.hit += sampled.hit;
          stats.occlusion_culled += culled;
        },
        [&](int done, int) { passes.report(progress, pass, done, bucket_count); });
    passes.finish(pass);
  }
  stats.grids = grid_counts.grids;
  stats.micropolygons = grid_counts.micropolygons;
  stats.shaded_vertices = grid_counts.shaded_vertices;
  stats.displacement_overruns = grid_counts.displacement_overruns;
  warn_about_displacement(scene, stats.displacement_overruns, stats.warnings);
  if (grid_counts.measured > 0) {
    stats.area_min_px = grid_counts.area_min;
    stats.area_max_px = grid_counts.area_max;
    stats.area_mean_px = grid_counts.area_sum / double(grid_counts.measured);
  }
  stats.samples_tested = hider_counts.tested;
  stats.samples_hit = hider_counts.hit;
  stats.seconds = passes.seconds();
  stats.cancelled = passes.cancelled();
  stats.time_limited = passes.time_limited();
  return stats;
}

}  // namespace obscura::reyes
