// Launching the built CLI under mpirun, for the tests of distributed rendering. The build passes
// OBSCURA_MPIEXEC (the mpiexec CMake found) only when it has MPI; without it, or where mpirun
// cannot start a job on this machine, the tests that need it skip and say why.
#pragma once

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "run_command.h"
#include "test_paths.h"

namespace obscura::test {

// Quoted for the shell (paths here hold no single quote).
inline std::string quoted(const std::string& text) {
  // (Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on `"'" + std::string`.)
  std::string out(1, '\'');
  out.append(text).push_back('\'');
  return out;
}

// mpirun as this suite needs it whoever runs it: root is allowed (CI runs as root) and more ranks
// than cores (CI has two), set through Open MPI's variables, which other MPIs ignore; and the job
// keeps its session files in `session_dir`, an empty directory of its own. (Open MPI 4 creates
// one directory per user under TMPDIR, and of two jobs starting at once one can fail creating it
// — "mkdir … File exists" — as tests running side by side do.)
inline std::string mpirun_command(const std::string& session_dir) {
#ifdef OBSCURA_MPIEXEC
  return "env TMPDIR=" + quoted(session_dir) +
         " OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1"
         " OMPI_MCA_rmaps_base_oversubscribe=1 " +
         quoted(OBSCURA_MPIEXEC);
#else
  (void)session_dir;
  return "";
#endif
}

// Why MPI jobs cannot run here, or empty when they can (probed once: `mpirun -np 1 true`).
inline const std::string& why_mpi_cannot_run() {
  static const std::string why = [] {
#ifdef OBSCURA_MPIEXEC
    const std::string session_dir = make_temp_dir("ompi");
    // Bounded: an MPI that cannot reach its own processes (a sandbox, a broken install) may
    // wait forever rather than fail.
    CommandResult probe = run_shell("timeout 60 " + mpirun_command(session_dir) + " -np 1 true");
    std::filesystem::remove_all(session_dir);
    if (probe.exit_code == 0) return std::string();
    return "`mpirun -np 1 true` fails here (exit " + std::to_string(probe.exit_code) + "):\n" +
           probe.output;
#else
    return std::string(
        "this build has no MPI (OBSCURA_MPI is off, or CMake found no MPI: scripts/setup "
        "installs Open MPI)");
#endif
  }();
  return why;
}

// A CLI test that needs mpirun: skipped, with the reason, where it cannot run.
class MpiCliTest : public TempDirTest {
 protected:
  void SetUp() override {
    TempDirTest::SetUp();
    if (!why_mpi_cannot_run().empty()) GTEST_SKIP() << why_mpi_cannot_run();
    // Beside the test's directory, not in it: the tests check what a command left there.
    sessions_ = make_temp_dir("ompi");
  }
  void TearDown() override {
    if (!sessions_.empty()) std::filesystem::remove_all(sessions_);
    TempDirTest::TearDown();
  }

  // `mpirun` as a shell command line, with session files of its own (see mpirun_command).
  std::string mpirun() {
    const std::string session_dir = sessions_ + "/" + std::to_string(jobs_++);
    std::filesystem::create_directory(session_dir);
    return mpirun_command(session_dir);
  }
  // `mpirun -np RANKS obscura ARGUMENTS` as a shell command line.
  std::string mpirun_obscura(int ranks, const std::string& arguments) {
    return mpirun() + " -np " + std::to_string(ranks) + " " + quoted(cli_path()) + " " + arguments;
  }

 private:
  std::string sessions_;
  int jobs_ = 0;
};

}  // namespace obscura::test
