// `obscura render --shard I/N` and `obscura merge`: a frame split across independent processes —
// tasks of a farm manager (Deadline, Flamenco) or a shell loop — without MPI.
//
// Part I renders the tiles an MPI rank I of N would (film/work_share.h) and writes them to a
// partial film: an OpenEXR data file whose channels are the film's sums (R, G, B = Σ w·L, W = Σ w)
// and the auxiliary images ("albedo.R", "depth.Z", …), exact floats, with the part, the frame and
// a key of the render's settings in its header. `merge` checks that the parts belong together and
// are all there, and assembles them into the image a single process would have written,
// bit for bit.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "frame_render.h"

namespace obscura::app {

struct ShardSpec {
  int part = 0, parts = 1;
};

// "I/N" with 0 ≤ I < N; throws UsageError otherwise.
ShardSpec parse_shard(const std::string& text);

// Writes part `spec` of a frame. `job` identifies the render's settings (render_job_key).
void write_shard(const std::string& path, const RenderedFrame& frame, ShardSpec spec,
                 const std::string& job);

struct ShardFile {
  std::string path;
  ShardSpec spec;
  std::string job;
  RenderedFrame frame;  // the part's pixels; the others are zero
};

// Reads a partial film; throws obscura::Error naming the file and the field that is wrong.
ShardFile read_shard(const std::string& path);

// The whole frame from all N parts, each once, of the same render (same settings key, size,
// renderer, channels), assembled one part at a time: it holds the frame and the part being added,
// never every part (merge reads a part, adds it and lets it go). Throws obscura::Error naming
// what is missing or does not match. Parts that stopped at different sample counts (a time
// limit) give a frame marked partial.
class ShardMerger {
 public:
  // Checks the part against the first one added and copies its pixels into the frame.
  void add(ShardFile part);
  // The whole frame, once every part 0 … N−1 has been added.
  RenderedFrame finish();

 private:
  std::optional<ShardFile> whole_;  // the first part, the others' pixels added to it
  std::map<int, std::string> paths_;
};

// All the parts at once, through a ShardMerger.
RenderedFrame merge_shards(const std::vector<ShardFile>& shards);

}  // namespace obscura::app
