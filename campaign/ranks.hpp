// The other processes of an `mpirun -np P tripack campaign ...` launch, as the campaign sees
// them (OpenMPI; the only file that includes mpi.h is ranks_mpi.cpp, compiled when CMake finds
// MPI; ranks_none.cpp stands in otherwise). Rank 0 hands out work units one at a time and is the
// only writer of the database; every other rank asks for a unit, runs it and sends back its
// RunRecord. Only the thread that created the link calls it (MPI_THREAD_FUNNELED), so rank 0's
// own worker threads never touch MPI.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "campaign/work_unit.hpp"

namespace tripack::campaign {

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

  // Rank 0. A worker's message, if one is waiting (never blocks): `from` and the encoded run it
  // finished, empty on its first request.
  struct Report {
    int from = 0;
    std::string run;
  };
  std::optional<Report> poll_report();
  void send_unit(int to, const WorkUnit& unit);
  void send_stop(int to);

  // Other ranks: report the last unit's run (empty at first) and wait for the next unit; none
  // means stop.
  std::optional<WorkUnit> report_and_wait(const std::string& run);

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace tripack::campaign
