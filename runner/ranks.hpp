// The runner's MPI executor (runner/runner.hpp) for an `mpirun -np P tripack campaign ...` launch
// (OpenMPI; the only file that includes mpi.h is ranks_mpi.cpp, compiled when CMake finds MPI;
// ranks_none.cpp stands in otherwise). Rank 0 hands out item indices one at a time and is the
// only process that sees results (`finished`), so it alone writes the database; every other rank
// asks for an item, runs it and sends back the text its run() returned. Only the thread that
// created the link calls MPI (MPI_THREAD_FUNNELED), so rank 0's own worker threads never do.
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <string>

#include "runner/runner.hpp"

namespace tripack {

// The number of ranks mpirun started this process among (its environment:
// OMPI_COMM_WORLD_SIZE, or PMI_SIZE under MPICH-style launchers); 1 when started alone.
int launched_ranks();
bool built_with_mpi();

class RankLink {
 public:
  // MPI_Init_thread; throws std::runtime_error when built without MPI or MPI cannot start.
  RankLink();
  ~RankLink();  // MPI_Finalize
  RankLink(const RankLink&) = delete;
  RankLink& operator=(const RankLink&) = delete;

  int rank() const;
  int size() const;

  // Rank 0. A worker's message, if one is waiting (never blocks): `from` and the result of the
  // item it finished, empty on its first request.
  struct Report {
    int from = 0;
    std::string result;
  };
  std::optional<Report> poll_report();
  void send_item(int to, std::size_t index);
  void send_stop(int to);

  // Other ranks: report the last item's result (empty at first) and wait for the next item;
  // none means stop.
  std::optional<std::size_t> report_and_wait(const std::string& result);

 private:
  struct State;
  std::unique_ptr<State> state_;
};

// Rank 0 serves the other ranks from its main thread and runs `threads` workers of its own
// (0: it only hands out items and records results).
class RankExecutor final : public Executor {
 public:
  explicit RankExecutor(int threads);
  JobOutcome run_items(const JobItems& items, const CancelToken* cancel) const override;
  int rank() const override { return link_->rank(); }
  int size() const { return link_->size(); }

 private:
  std::unique_ptr<RankLink> link_;
  int threads_;
};

// The executor of this launch: MPI ranks under mpirun (launched_ranks() > 1), else threads.
std::unique_ptr<Executor> executor_for_launch(int threads);

}  // namespace tripack
