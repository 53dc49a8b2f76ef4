#include "view_command.h"

#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include <memory>
#include <string>
#include <vector>

#include "obscura/io/image_io.h"
#include "option_ranges.h"
#include "render_command.h"
#include "render_options.h"
#include "view_server.h"

namespace obscura::app {

namespace {

// Every frame of the view allocates the same large buffers again (film, render target, AOVs,
// images: about 50 MB at 640 × 360), which glibc serves from fresh mmaps and hands back to the
// kernel when freed: each frame then page-faults all of them in again, about 40 % of a raster
// frame's CPU time. The server keeps them in its heap instead, at the cost of holding its peak.
void keep_frame_buffers_in_the_heap() {
#if defined(__GLIBC__)
  mallopt(M_MMAP_THRESHOLD, 1 << 30);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
#endif
}

}  // namespace

void add_view_command(CLI::App& app, int argc, char** argv) {
  // The options are parsed here to check them and for --help; the view parses its own arguments
  // again, as `obscura render` would, for every frame (view_renderer.cpp).
  auto options = std::make_shared<RenderOptions>();
  auto server = std::make_shared<ViewServerOptions>();
  CLI::App* view = app.add_subcommand(
      "view",
      "Show the scene in a web browser and handle the camera there: a server on 127.0.0.1 "
      "prints the page's address (docs/view.md)");
  view->add_option("scene", options->scene,
                   "A scene file (watched: an edit reloads the view) or a built-in scene name; "
                   "default: the Cornell box");
  add_frame_options(*view, *options);
  view->add_option("--port", server->port, "The port to listen on, on 127.0.0.1 (0: a free one)")
      ->check(integer_in(0, 65535))
      ->capture_default_str()
      ->group("View");
  view->add_flag("--open", server->open, "Ask the desktop to open the page in a browser")
      ->group("View");
  view->add_option("-o,--output", server->output,
                   "Where the page's Save writes the frame shown; the format follows the "
                   "extension, as render's -o")
      ->capture_default_str()
      ->group("View");
  view->add_option("--max-requests-per-second", server->max_requests_per_second,
                   "Requests the server takes in a second; more are answered 429 (Too Many "
                   "Requests)")
      ->check(integer_in(1, 1000000))
      ->capture_default_str()
      ->group("View");
  view->add_flag("--no-watch", server->no_watch, "Do not reload the scene file when it changes")
      ->group("View");
  // main() runs `obscura view …` with `view` as the first word (the commands are checked there).
  std::vector<std::string> arguments;
  for (int i = 2; i < argc; ++i) arguments.emplace_back(argv[i]);
  // The options live as long as the parser that writes into them.
  view->callback([options, server, arguments] {
    check_output_path(server->output, "--output");  // before serving, not at the first save
    ViewServerOptions run = *server;
    run.arguments = arguments;
    keep_frame_buffers_in_the_heap();
    run_view_server(run);
  });
}

}  // namespace obscura::app
