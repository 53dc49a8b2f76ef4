#include "team.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <map>

#ifdef OBSCURA_WITH_MPI
#include "mpi_team_plugin.h"
#include "obscura/io/plugin_loader.h"
#include "obscura/math/error.h"
#endif

namespace obscura::app {

namespace {

#ifdef OBSCURA_WITH_MPI
// The MPI team plugin, once loaded (only under a launcher).
const MpiTeamPlugin* mpi_team_plugin = nullptr;

const MpiTeamPlugin& load_mpi_team_plugin() {
  try {
    using Entry = const MpiTeamPlugin* (*)();
    auto entry = reinterpret_cast<Entry>(
        load_plugin_entry(kMpiTeamPluginFile, kMpiTeamEntryPoint, "join the MPI job"));
    return *entry();
  } catch (const Error& e) {
    throw TeamFailure(e.what());
  }
}
#endif

std::unique_ptr<Team>& current_team() {
  static std::unique_ptr<Team> team = std::make_unique<Team>();
  return team;
}

// The size of the job a launcher started this process in, from the variables launchers set
// (Open MPI, MPICH/Hydra and Slurm's PMI); 0 when none is set: not started by a launcher.
int launched_job_size() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"})
    if (const char* value = std::getenv(name)) return std::max(1, std::atoi(value));
  return 0;
}

}  // namespace

void Team::run_phase(const std::function<void()>& phase) {
  if (alone()) return phase();
  std::string error;
  try {
    phase();
  } catch (const TeamFailure& e) {
    error = e.what();
  } catch (const std::exception& e) {
    error = e.what();
    if (error.empty()) error = "failed";
  }
  std::vector<std::string> errors = gather_errors(error);
  bool failed = false;
  if (leads()) {
    // Ranks with the same message are named together: "ranks 0-3: cannot open …".
    std::map<std::string, std::vector<int>> by_message;
    for (size_t r = 0; r < errors.size(); ++r)
      if (!errors[r].empty()) by_message[errors[r]].push_back(int(r));
    std::string report;
    for (const auto& [message, ranks] : by_message) {
      std::string who = ranks.size() == 1 ? "rank " : "ranks ";
      for (size_t i = 0; i < ranks.size(); ++i) {
        if (i) who.push_back(',');
        who.append(std::to_string(ranks[i]));
      }
      if (ranks.size() == errors.size()) who = "every rank";
      if (!report.empty()) report.append("\nobscura: error: ");
      report.append(who).append(": ").append(message);
    }
    failed = !report.empty();
    settle(failed ? StopVerdict::kCancelled : StopVerdict::kGoOn);
    if (failed) throw TeamFailure(report);
  } else {
    failed = settle(StopVerdict::kGoOn) != StopVerdict::kGoOn;
    if (failed) throw TeamFailure("");
  }
}

std::vector<int> Team::ticket_owners(const std::vector<int64_t>& mine, int64_t count) {
  std::vector<int> owners(size_t(count), rank());
  (void)mine;
  return owners;
}

void Team::abort(int status) {
  std::exit(status);
}

Team& team() {
  return *current_team();
}

void join_team([[maybe_unused]] int& argc, [[maybe_unused]] char**& argv) {
#ifdef OBSCURA_WITH_MPI
  // MPI is started only under a launcher: a plain `obscura` does not pay for MPI_Init.
  if (launched_job_size() > 0) {
    mpi_team_plugin = &load_mpi_team_plugin();
    current_team() = mpi_team_plugin->make(argc, argv);
  }
#else
  if (launched_job_size() > 1)
    throw TeamFailure(
        "started by mpirun as one of " + std::to_string(launched_job_size()) +
        " ranks, but this obscura was built without MPI: install Open MPI (scripts/setup) and "
        "build again, or render with one process (--shard I/N and `obscura merge` split a frame "
        "without MPI)");
#endif
}

void leave_team() {
#ifdef OBSCURA_WITH_MPI
  if (mpi_team_plugin) mpi_team_plugin->finalize();
#endif
}

std::string rank_prefix() {
  return team().alone() ? "" : "rank " + std::to_string(team().rank()) + ": ";
}

}  // namespace obscura::app
