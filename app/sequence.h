// `obscura render --frames A:B[:STEP] --fps F`: an animated scene (glTF animations, JSON motion
// keys, a moving camera) rendered frame by frame. Frame n is exposed around n / F seconds, as
// `--time n/F` would; its image goes to the output pattern with n filled in (out_%04d.exr →
// out_0012.exr), or all frames into one .y4m video.
//
// Numbered files can be resumed: a frame whose file is already there, readable, of the frame's
// size, not marked partial and whose every pixel reads back is skipped (files are only ever renamed
// into place when complete, so a crash leaves none half-written). A video is written whole or not
// at all.
//
// Under mpirun, frames are handed out one at a time to whichever rank is free (a counter on rank
// 0 that every rank increments atomically), and each rank renders its frames alone. Numbered
// files are written by the rank that rendered them, so the output directory must be one all ranks
// see (as the scene must be); a video is assembled on rank 0 in frame order.
#pragma once

#include <string>

#include "frame_files.h"
#include "render_options.h"
#include "team.h"

namespace obscura::app {

// Renders the sequence the options ask for (options.frames non-empty).
void run_sequence(RenderOptions options, Team& team);

}  // namespace obscura::app
