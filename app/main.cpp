// obscura: the command line. main only wires subcommands; each lives in its own file.
#include <csignal>
#include <cstdio>
#include <exception>
#include <new>
#include <string>

#include <CLI/CLI.hpp>

#include "camera_command.h"
#include "color_command.h"
#include "image_command.h"
#include "info_command.h"
#include "obscura/math/error.h"
#include "partial_render.h"
#include "raster_clip_command.h"
#include "render_command.h"
#include "usage_error.h"

int main(int argc, char** argv) {
  // Over a file-size limit (ulimit -f) a write then fails with EFBIG and is reported like a full
  // disk, naming the output, instead of SIGXFSZ killing the process with the file half written.
  std::signal(SIGXFSZ, SIG_IGN);
  CLI::App app("Obscura: a physical camera that turns a 3D scene into an image.", "obscura");
  app.set_version_flag("--version", "obscura " OBSCURA_VERSION);
  app.require_subcommand(1);
  obscura::app::add_render_command(app);
  obscura::app::add_camera_command(app);
  obscura::app::add_color_command(app);
  obscura::app::add_image_command(app);
  obscura::app::add_info_command(app);
  obscura::app::add_raster_clip_command(app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "obscura: error: %s\nRun 'obscura --help' for usage.\n", e.what());
    return 2;
  } catch (const obscura::app::UsageError& e) {
    std::fprintf(stderr, "obscura: error: %s\n", e.what());
    return 2;
  } catch (const std::bad_alloc&) {
    // Anywhere: a scene, image or option asked for more memory than there is. Name the command so
    // the message is not mistaken for a bug; the options' ranges keep this rare.
    std::string command = "obscura";
    for (const CLI::App* sub = &app; !sub->get_subcommands().empty();) {
      sub = sub->get_subcommands().front();
      command += " " + sub->get_name();
    }
    std::fprintf(stderr,
                 "obscura: out of memory while running '%s': the scene, the image size or the "
                 "sample count needs more memory than this machine gives\n",
                 command.c_str());
    return 1;
  } catch (const obscura::Error& e) {
    std::fprintf(stderr, "obscura: error: %s\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "obscura: internal error: %s\n", e.what());
    return 1;
  }
  // 0, or how a render ended early (app/partial_render.h).
  return obscura::app::exit_status();
}
