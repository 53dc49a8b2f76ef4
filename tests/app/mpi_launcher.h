// Launching the built CLI under mpirun, for the tests of distributed rendering. The build passes
// OBSCURA_MPIEXEC (the mpiexec CMake found) only when it has MPI; without it, or where mpirun
// cannot start a job on this machine, the tests that need it skip and say why.
#pragma once

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

// mpirun with what this suite needs of it whoever runs it: root is allowed (CI runs as root), and
// more ranks than cores (CI has two). Set through Open MPI's variables, which other MPIs ignore.
inline std::string mpirun_command() {
#ifdef OBSCURA_MPIEXEC
  return "env OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 "
         "OMPI_MCA_rmaps_base_oversubscribe=1 " +
         quoted(OBSCURA_MPIEXEC);
#else
  return "";
#endif
}

// `mpirun -np RANKS obscura ARGUMENTS` as a shell command line.
inline std::string mpirun_obscura(int ranks, const std::string& arguments) {
  return mpirun_command() + " -np " + std::to_string(ranks) + " " + quoted(cli_path()) + " " +
         arguments;
}

// Why MPI jobs cannot run here, or empty when they can (probed once: `mpirun -np 1 true`).
inline const std::string& why_mpi_cannot_run() {
  static const std::string why = [] {
#ifdef OBSCURA_MPIEXEC
    CommandResult probe = run_shell(mpirun_command() + " -np 1 true");
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
  }
};

}  // namespace obscura::test
