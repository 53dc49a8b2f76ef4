// The processes that run one command together: this process alone, or the ranks of an MPI job
// (`mpirun -np N obscura render …`, see docs/distributed.md).
//
// Rank 0 leads: it reads the command's output paths, draws the progress and writes every file;
// the other ranks render their share and hand it to rank 0. Only the main thread talks to the
// team (the renderers' worker threads never do).
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "obscura/film/image.h"
#include "obscura/film/work_share.h"

namespace obscura::app {

// A phase failed on some rank. Thrown on every rank; rank 0's message lists each failing rank's
// error, the others' is empty (main prints nothing for an empty message).
class TeamFailure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class Team {
 public:
  virtual ~Team() = default;

  virtual int rank() const { return 0; }
  virtual int size() const { return 1; }
  bool alone() const { return size() == 1; }
  bool leads() const { return rank() == 0; }

  // The most severe of the verdicts every rank passes (each rank calls it equally often).
  virtual StopVerdict settle(StopVerdict own) { return own; }
  // The sum over the ranks of each one's value.
  virtual double sum(double own) { return own; }
  // Rank 0 receives the pixels each other rank owns under `deal` (rank = part) into its own
  // `image`, in rank order; the other ranks send theirs and keep their image as it was.
  virtual void gather(const TileDeal&, Image&) {}
  // Bytes this process has sent to others so far (pixels and messages).
  virtual uint64_t bytes_sent() const { return 0; }

  // Runs a phase every rank goes through (validating, loading the scene). Alone, its exceptions
  // pass through untouched. In a team every rank learns whether any rank failed, and then all
  // throw TeamFailure, so that no rank waits for one that has given up.
  void run_phase(const std::function<void()>& phase);

  // A counter shared by all ranks: each call, on any rank, returns the next number from 0 on.
  // Between open_counter() and close_counter(), which every rank calls together.
  virtual void open_counter() { next_ticket_ = 0; }
  virtual int64_t take_ticket() { return next_ticket_++; }
  virtual void close_counter() {}

  // Sends bytes to one rank / receives them from one (blocking).
  virtual void send(int /*to*/, const std::vector<uint8_t>& /*bytes*/) {}
  virtual std::vector<uint8_t> receive(int /*from*/) { return {}; }
  // Which rank took each of the tickets 0 … count − 1 (every rank learns the same list).
  virtual std::vector<int> ticket_owners(const std::vector<int64_t>& mine, int64_t count);

  // Ends every rank's process at once with `status` (an error no phase caught).
  [[noreturn]] virtual void abort(int status);

 protected:
  // Each rank's error message (empty: no error), known on rank 0; on the others, empty.
  virtual std::vector<std::string> gather_errors(const std::string& own) { return {own}; }

 private:
  int64_t next_ticket_ = 0;
};

// This process's team: alone unless join_team found an MPI launch.
Team& team();

// Called first in main: joins the MPI job when the process was started by mpirun (or another
// MPI launcher) and Obscura was built with MPI; throws TeamFailure with a clear message when it
// was started by mpirun with more than one rank but built without MPI.
void join_team(int& argc, char**& argv);
// Called last in main (a no-op alone).
void leave_team();

// Prefix for messages from this rank ("rank 2: "), empty alone.
std::string rank_prefix();

}  // namespace obscura::app
