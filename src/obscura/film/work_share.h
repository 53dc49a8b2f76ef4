// Rendering one frame as a team: several processes (MPI ranks, or `--shard` parts run anywhere)
// each render a share of the frame, and the shares are put together afterwards.
//
// The frame is split by pixels, never by samples: every pixel is rendered whole by one process,
// which sums its samples in the same order a lone process would, so the assembled image is
// bit-identical to a single process's for any number of parts. (Splitting a pixel's samples would
// need the parts' sums added back in the original order, which floating-point addition does not
// allow.) The renderer's tiles are dealt round-robin — tile t to part t mod parts, tiles numbered
// row by row — so every part gets tiles from all over the image, and expensive regions (glass, a
// dense mesh) are shared out instead of landing on one part.
#pragma once

#include <functional>

#include "obscura/film/image.h"

namespace obscura {

// Why a renderer stops between passes (tracer) or frames (rasterizer), most severe last.
enum class StopVerdict { kGoOn, kTimeLimit, kCancelled };

// Which pixels go to which part: tiles of tile_size × tile_size pixels over a width × height
// frame (the last row and column of tiles may be smaller), dealt round-robin to `parts` parts.
struct TileDeal {
  int width = 0, height = 0;
  int tile_size = 16;
  int parts = 1;

  int columns() const { return (width + tile_size - 1) / tile_size; }
  int tile_at(int x, int y) const { return (y / tile_size) * columns() + x / tile_size; }
  int owner_of_tile(int tile) const { return tile % parts; }
  int owner(int x, int y) const { return owner_of_tile(tile_at(x, y)); }
  // Pixels part `part` owns.
  size_t pixel_count(int part) const;
};

// One process's share of a frame, as the renderers take it.
struct WorkShare {
  int part = 0, parts = 1;  // 0 ≤ part < parts
  // Called by every part after each pass (tracer) or frame (rasterizer) with its own verdict;
  // returns the team's, the same on every part (the most severe), so that all parts stop after
  // the same pass. Empty: the process renders alone and its own verdict stands.
  std::function<StopVerdict(StopVerdict)> settle = {};

  bool alone() const { return parts == 1; }
  bool owns_tile(int tile) const { return tile % parts == part; }
  StopVerdict agree(StopVerdict own) const { return settle ? settle(own) : own; }
};

// The owned pixels of `image`, packed in row-major order (all channels of a pixel together), and
// the inverse: writing packed pixels back into the positions `part` owns. The packed order is
// what travels between processes; unpacking every part's pixels into one image assembles it.
std::vector<float> pack_owned_pixels(const TileDeal& deal, int part, const Image& image);
// Throws obscura::Error when `packed` does not hold exactly the part's pixels × channels.
void unpack_owned_pixels(const TileDeal& deal, int part, const std::vector<float>& packed,
                         Image& image);

}  // namespace obscura
