// `obscura merge PARTS... -o IMAGE`: assembles the partial films of `obscura render --shard I/N`
// into the image (and auxiliary images) one process would have written.
#pragma once

#include <CLI/CLI.hpp>

namespace obscura::app {

void add_merge_command(CLI::App& app);

}  // namespace obscura::app
