// `obscura view`: the live view (docs/view.md). A web server on 127.0.0.1 shows the scene in a
// browser, the camera handled on the page, rendered as `obscura render` would with the same
// options.
#pragma once

#include <CLI/CLI.hpp>

namespace obscura::app {

// `argc`/`argv`: main's command line, which the view keeps to offer the page's camera back as an
// `obscura render` command line.
void add_view_command(CLI::App& app, int argc, char** argv);

}  // namespace obscura::app
