// The team of an MPI job (built when CMake finds MPI, as the plugin of mpi_team_plugin.h; see
// team.h).
#ifdef OBSCURA_WITH_MPI

#include <mpi.h>

#include <algorithm>
#include <climits>
#include <cstdio>

#include "mpi_team_plugin.h"
#include "obscura/math/error.h"
#include "team.h"

namespace obscura::app {

namespace {

// MPI counts are ints: long messages go in pieces of at most this many elements.
constexpr size_t kMaxPiece = size_t(1) << 28;

class MpiTeam : public Team {
 public:
  MpiTeam() {
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
  }
  ~MpiTeam() override { close_counter(); }

  int rank() const override { return rank_; }
  int size() const override { return size_; }

  StopVerdict settle(StopVerdict own) override {
    int mine = int(own), team = 0;
    MPI_Allreduce(&mine, &team, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
    return StopVerdict(team);
  }

  double sum(double own) override {
    double total = 0;
    MPI_Allreduce(&own, &total, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
    return total;
  }

  void gather(const TileDeal& deal, Image& image) override {
    if (deal.parts != size_)
      throw Error("gather", "a deal for " + std::to_string(deal.parts) + " parts in a team of " +
                                std::to_string(size_));
    if (rank_ != 0) {
      send_floats(0, pack_owned_pixels(deal, rank_, image));
      return;
    }
    // Rank order: the assembled image never depends on which rank finished first.
    for (int r = 1; r < size_; ++r) {
      std::vector<float> packed(deal.pixel_count(r) * size_t(image.channels));
      receive_floats(r, packed);
      unpack_owned_pixels(deal, r, packed, image);
    }
  }

  uint64_t bytes_sent() const override { return bytes_sent_; }

  void open_counter() override {
    close_counter();
    counter_ = 0;
    MPI_Win_create(&counter_, rank_ == 0 ? sizeof counter_ : 0, sizeof counter_, MPI_INFO_NULL,
                   MPI_COMM_WORLD, &window_);
    open_ = true;
  }

  int64_t take_ticket() override {
    if (!open_) throw Error("team", "take_ticket() outside open_counter()/close_counter()");
    const int64_t one = 1;
    int64_t ticket = 0;
    // An atomic fetch-and-add on rank 0's counter: no rank has to stop rendering to serve it.
    MPI_Win_lock(MPI_LOCK_SHARED, 0, 0, window_);
    MPI_Fetch_and_op(&one, &ticket, MPI_INT64_T, 0, 0, MPI_SUM, window_);
    MPI_Win_unlock(0, window_);
    return ticket;
  }

  void close_counter() override {
    if (!open_) return;
    MPI_Win_free(&window_);
    open_ = false;
  }

  void send(int to, const std::vector<uint8_t>& bytes) override {
    uint64_t size = bytes.size();
    MPI_Send(&size, 1, MPI_UINT64_T, to, kTagSize, MPI_COMM_WORLD);
    for (size_t at = 0; at < bytes.size(); at += kMaxPiece)
      MPI_Send(bytes.data() + at, int(std::min(kMaxPiece, bytes.size() - at)), MPI_BYTE, to,
               kTagData, MPI_COMM_WORLD);
    bytes_sent_ += sizeof size + bytes.size();
  }

  std::vector<uint8_t> receive(int from) override {
    uint64_t size = 0;
    MPI_Recv(&size, 1, MPI_UINT64_T, from, kTagSize, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    std::vector<uint8_t> bytes(size);
    for (size_t at = 0; at < bytes.size(); at += kMaxPiece)
      MPI_Recv(bytes.data() + at, int(std::min(kMaxPiece, bytes.size() - at)), MPI_BYTE, from,
               kTagData, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    return bytes;
  }

  std::vector<int> ticket_owners(const std::vector<int64_t>& mine, int64_t count) override {
    int my_count = int(mine.size());
    std::vector<int> counts(static_cast<size_t>(size_)), offsets(static_cast<size_t>(size_));
    MPI_Allgather(&my_count, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
    int total = 0;
    for (int r = 0; r < size_; ++r) offsets[size_t(r)] = total, total += counts[size_t(r)];
    std::vector<int64_t> all(size_t(std::max(total, 1)));
    MPI_Allgatherv(mine.data(), my_count, MPI_INT64_T, all.data(), counts.data(), offsets.data(),
                   MPI_INT64_T, MPI_COMM_WORLD);
    std::vector<int> owners(size_t(count), -1);
    for (int r = 0; r < size_; ++r)
      for (int i = 0; i < counts[size_t(r)]; ++i) {
        int64_t ticket = all[size_t(offsets[size_t(r)] + i)];
        if (ticket >= 0 && ticket < count) owners[size_t(ticket)] = r;
      }
    return owners;
  }

  [[noreturn]] void abort(int status) override {
    std::fflush(stdout);
    std::fflush(stderr);
    MPI_Abort(MPI_COMM_WORLD, status);
    std::_Exit(status);  // MPI_Abort does not return; this keeps the compiler sure of it
  }

 protected:
  std::vector<std::string> gather_errors(const std::string& own) override {
    int length = int(own.size());
    std::vector<int> lengths(static_cast<size_t>(size_)), offsets(static_cast<size_t>(size_));
    MPI_Gather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
    int total = 0;
    if (rank_ == 0)
      for (int r = 0; r < size_; ++r) offsets[size_t(r)] = total, total += lengths[size_t(r)];
    std::string all(size_t(total), '\0');
    MPI_Gatherv(own.data(), length, MPI_CHAR, all.data(), lengths.data(), offsets.data(), MPI_CHAR,
                0, MPI_COMM_WORLD);
    std::vector<std::string> errors;
    if (rank_ == 0)
      for (int r = 0; r < size_; ++r)
        errors.push_back(all.substr(size_t(offsets[size_t(r)]), size_t(lengths[size_t(r)])));
    return errors;
  }

 private:
  static constexpr int kTagSize = 1, kTagData = 2, kTagPixels = 3;

  void send_floats(int to, const std::vector<float>& values) {
    for (size_t at = 0; at < values.size(); at += kMaxPiece)
      MPI_Send(values.data() + at, int(std::min(kMaxPiece, values.size() - at)), MPI_FLOAT, to,
               kTagPixels, MPI_COMM_WORLD);
    bytes_sent_ += values.size() * sizeof(float);
  }
  void receive_floats(int from, std::vector<float>& values) {
    for (size_t at = 0; at < values.size(); at += kMaxPiece)
      MPI_Recv(values.data() + at, int(std::min(kMaxPiece, values.size() - at)), MPI_FLOAT, from,
               kTagPixels, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  }

  int rank_ = 0, size_ = 1;
  uint64_t bytes_sent_ = 0;
  int64_t counter_ = 0;
  MPI_Win window_ = MPI_WIN_NULL;
  bool open_ = false;
};

bool initialized_here = false;

std::unique_ptr<Team> make_mpi_team(int& argc, char**& argv) {
  int provided = 0;
  // Only the main thread calls MPI; the renderers' worker threads never do.
  if (MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS)
    throw TeamFailure("MPI could not be started (MPI_Init_thread failed)");
  initialized_here = true;
  return std::make_unique<MpiTeam>();
}

void finalize_mpi_team() {
  if (!initialized_here) return;
  team().close_counter();
  MPI_Finalize();
  initialized_here = false;
}

}  // namespace

}  // namespace obscura::app

extern "C" __attribute__((visibility("default"))) const obscura::app::MpiTeamPlugin*
obscura_mpi_team_v1() {
  static const obscura::app::MpiTeamPlugin plugin{&obscura::app::make_mpi_team,
                                                  &obscura::app::finalize_mpi_team};
  return &plugin;
}

#endif  // OBSCURA_WITH_MPI
