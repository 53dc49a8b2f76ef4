// `obscura info SCENE`: what a scene holds, how long it took to load and how much memory it uses.
#pragma once

#include <CLI/CLI.hpp>

namespace obscura::app {

void add_info_command(CLI::App& app);

}  // namespace obscura::app
