// The live view's HTTP server (cpp-httplib): the page, its event stream and its small API, on
// 127.0.0.1 only, every request carrying the session's random token (docs/view.md, "Security").
#pragma once

#include <string>
#include <vector>

namespace obscura::app {

struct ViewServerOptions {
  std::vector<std::string> arguments;  // the command line after `view`
  int port = 0;                        // 0: a free port
  bool open = false;                   // --open: xdg-open the page
  bool no_watch = false;
  int max_requests_per_second = 400;  // beyond it, 429 until the next second
  std::string output = "view.png";    // -o: where the page's "save" writes the frame
};

// Loads the scene, serves until SIGINT or SIGTERM. Prints the page's address (with its token) on
// stdout. Throws obscura::Error when the port is taken or the scene does not load; UsageError
// when built without cpp-httplib.
void run_view_server(const ViewServerOptions& options);

}  // namespace obscura::app
