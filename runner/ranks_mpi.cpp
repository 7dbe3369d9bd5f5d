// The runner's MPI messages (OpenMPI): a worker sends tag kReport (its last item's result, empty
// at first); rank 0 answers tag kItem (the item's index) or tag kStop. Rank 0 polls with MPI_Iprobe
// and sleeps between polls, so waiting for workers costs no core while its own threads compute.
#include <mpi.h>

#include <cstdint>
#include <stdexcept>
#include <string>

#include "runner/ranks.hpp"
#include "runner/ranks_env.hpp"

namespace tripack {

namespace {
constexpr int kReport = 1, kItem = 2, kStop = 3;
}  // namespace

struct RankLink::State {
  int rank = 0, size = 1;
};

int launched_ranks() {
  return ranks_from_environment();
}
bool built_with_mpi() {
  return true;
}

RankLink::RankLink() : state_(std::make_unique<State>()) {
  int provided = 0;
  if (MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS)
    throw std::runtime_error("MPI_Init_thread failed");
  if (provided < MPI_THREAD_FUNNELED) {
    MPI_Finalize();
    throw std::runtime_error("this MPI library cannot run a rank with threads (FUNNELED)");
  }
  MPI_Comm_rank(MPI_COMM_WORLD, &state_->rank);
  MPI_Comm_size(MPI_COMM_WORLD, &state_->size);
}

RankLink::~RankLink() {
  MPI_Finalize();
}

int RankLink::rank() const {
  return state_->rank;
}
int RankLink::size() const {
  return state_->size;
}

std::optional<RankLink::Report> RankLink::poll_report() {
  int waiting = 0;
  MPI_Status status;
  MPI_Iprobe(MPI_ANY_SOURCE, kReport, MPI_COMM_WORLD, &waiting, &status);
  if (!waiting) return std::nullopt;
  int length = 0;
  MPI_Get_count(&status, MPI_CHAR, &length);
  Report report;
  report.from = status.MPI_SOURCE;
  report.result.resize(static_cast<std::size_t>(length));
  MPI_Recv(report.result.data(), length, MPI_CHAR, status.MPI_SOURCE, kReport, MPI_COMM_WORLD,
           MPI_STATUS_IGNORE);
  return report;
}

void RankLink::send_item(int to, std::size_t index) {
  const auto message = static_cast<std::int64_t>(index);
  MPI_Send(&message, 1, MPI_INT64_T, to, kItem, MPI_COMM_WORLD);
}

void RankLink::send_stop(int to) {
  MPI_Send(nullptr, 0, MPI_INT64_T, to, kStop, MPI_COMM_WORLD);
}

std::optional<std::size_t> RankLink::report_and_wait(const std::string& result) {
  MPI_Send(result.data(), static_cast<int>(result.size()), MPI_CHAR, 0, kReport, MPI_COMM_WORLD);
  std::int64_t message = 0;
  MPI_Status status;
  MPI_Recv(&message, 1, MPI_INT64_T, 0, MPI_ANY_TAG, MPI_COMM_WORLD, &status);
  if (status.MPI_TAG == kStop) return std::nullopt;
  return static_cast<std::size_t>(message);
}

}  // namespace tripack
