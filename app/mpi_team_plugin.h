// The MPI team (mpi_team.cpp) is a plugin, libobscura_mpi_team.so, loaded only when a launcher
// (mpirun) started the process: Open MPI's libraries (libmpi, open-pal, open-rte, hwloc, libevent)
// are then not loaded and relocated by every plain `obscura` run. It resolves what it uses of the
// command line (Team, pack_owned_pixels, …) against the executable, which exports its symbols.
#pragma once

#include <memory>

#include "team.h"

namespace obscura::app {

struct MpiTeamPlugin {
  // Starts MPI and returns this process's team; throws TeamFailure when MPI cannot start.
  std::unique_ptr<Team> (*make)(int& argc, char**& argv);
  // Ends MPI (after make; a no-op otherwise).
  void (*finalize)();
};

inline constexpr const char* kMpiTeamPluginFile = "libobscura_mpi_team.so";
// `const MpiTeamPlugin* NAME()`; the version changes with MpiTeamPlugin or Team.
inline constexpr const char* kMpiTeamEntryPoint = "obscura_mpi_team_v1";

}  // namespace obscura::app
