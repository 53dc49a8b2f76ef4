// obscura: the command line. main only wires subcommands; each lives in its own file.
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <new>
#include <string>

#include <CLI/CLI.hpp>

#include "camera_command.h"
#include "color_command.h"
#include "dataset_command.h"
#include "image_command.h"
#include "info_command.h"
#include "merge_command.h"
#include "obscura/math/error.h"
#include "obscura/math/request_error.h"
#include "partial_render.h"
#include "raster_clip_command.h"
#include "render_command.h"
#include "team.h"
#include "usage_error.h"
#include "view_command.h"

namespace {

// Runs the command line; returns main's status. Errors print here, prefixed with the rank in an
// MPI job; one that escapes a rank outside a phase all ranks go through ends the whole job.
int run(int argc, char** argv);

}  // namespace

int main(int argc, char** argv) {
  try {
    obscura::app::join_team(argc, argv);
  } catch (const obscura::app::TeamFailure& e) {
    // Only the first rank speaks for a job that cannot start.
    const char* rank = std::getenv("OMPI_COMM_WORLD_RANK");
    if (!rank || std::string(rank) == "0") std::fprintf(stderr, "obscura: error: %s\n", e.what());
    return 2;
  }
  // Under mpirun only `render` and `dataset` work as a team; any other command runs once, on rank
  // 0.
  int status = 0;
  const char* command = argc > 1 ? argv[1] : "";
  if (obscura::app::team().leads() || std::string(command) == "render" ||
      std::string(command) == "dataset")
    status = run(argc, argv);
  obscura::app::leave_team();
  return status;
}

namespace {

// A failure on one rank outside a shared phase: the others may be waiting for it, so the
// whole job ends (alone, this just returns the status).
int fail(int status) {
  obscura::app::Team& team = obscura::app::team();
  if (!team.alone()) team.abort(status);
  return status;
}

int run(int argc, char** argv) {
  using obscura::app::rank_prefix;
  // Over a file-size limit (ulimit -f) a write then fails with EFBIG and is reported like a full
  // disk, naming the output, instead of SIGXFSZ killing the process with the file half written.
  std::signal(SIGXFSZ, SIG_IGN);
  CLI::App app("Obscura: a physical camera that turns a 3D scene into an image.", "obscura");
  app.set_version_flag("--version", "obscura " OBSCURA_VERSION);
  app.require_subcommand(1);
  obscura::app::add_render_command(app);
  obscura::app::add_dataset_command(app);
  obscura::app::add_camera_command(app);
  obscura::app::add_color_command(app);
  obscura::app::add_image_command(app);
  obscura::app::add_info_command(app);
  obscura::app::add_merge_command(app);
  obscura::app::add_raster_clip_command(app);
  obscura::app::add_view_command(app, argc, argv);

  // A first word that is neither an option nor a command is named as such (CLI11 would only
  // say that a command is required).
  if (argc > 1 && argv[1][0] != '-') {
    std::string commands;
    bool known = false;
    for (const CLI::App* command : app.get_subcommands({})) {
      commands += (commands.empty() ? "" : ", ") + command->get_name();
      known = known || command->check_name(argv[1]);
    }
    if (!known) {
      if (obscura::app::team().leads())
        std::fprintf(stderr,
                     "obscura: error: unknown command '%s'; the commands are %s\nRun 'obscura "
                     "--help' for usage.\n",
                     argv[1], commands.c_str());
      return 2;
    }
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // Every rank parses the same command line: rank 0 speaks for all.
    if (obscura::app::team().leads())
      std::fprintf(stderr, "obscura: error: %s\nRun 'obscura --help' for usage.\n", e.what());
    return 2;
  } catch (const obscura::app::TeamFailure& e) {
    // A phase failed on some rank; every rank is here, rank 0 with the report.
    if (*e.what()) std::fprintf(stderr, "obscura: error: %s\n", e.what());
    return 1;
  } catch (const obscura::app::UsageError& e) {
    std::fprintf(stderr, "obscura: %serror: %s\n", rank_prefix().c_str(), e.what());
    return fail(2);
  } catch (const obscura::RequestError& e) {  // a value asked for, as a usage error
    std::fprintf(stderr, "obscura: %serror: %s\n", rank_prefix().c_str(), e.what());
    return fail(2);
  } catch (const std::bad_alloc&) {
    // Anywhere: a scene, image or option asked for more memory than there is. Name the command so
    // the message is not mistaken for a bug; the options' ranges keep this rare.
    std::string command = "obscura";
    for (const CLI::App* sub = &app; !sub->get_subcommands().empty();) {
      sub = sub->get_subcommands().front();
      command += " " + sub->get_name();
    }
    std::fprintf(stderr,
                 "obscura: %sout of memory while running '%s': the scene, the image size or the "
                 "sample count needs more memory than this machine gives\n",
                 rank_prefix().c_str(), command.c_str());
    return fail(1);
  } catch (const obscura::Error& e) {
    std::fprintf(stderr, "obscura: %serror: %s\n", rank_prefix().c_str(), e.what());
    return fail(1);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "obscura: %sinternal error: %s\n", rank_prefix().c_str(), e.what());
    return fail(1);
  }
  // 0, or how a render ended early (app/partial_render.h).
  return obscura::app::exit_status();
}

}  // namespace
