// Built without MPI: jobs run on threads only; a launch by mpirun is refused (each rank
// would otherwise run the whole campaign on the same database).
#include <stdexcept>

#include "runner/ranks.hpp"
#include "runner/ranks_env.hpp"

namespace tripack {

struct RankLink::State {};

int launched_ranks() {
  return ranks_from_environment();
}
bool built_with_mpi() {
  return false;
}

RankLink::RankLink() {
  throw std::runtime_error(
      "this tripack was built without MPI (install libopenmpi-dev and rebuild), so it cannot run "
      "a campaign under mpirun");
}
RankLink::~RankLink() = default;
int RankLink::rank() const {
  return 0;
}
int RankLink::size() const {
  return 1;
}
std::optional<RankLink::Report> RankLink::poll_report() {
  return std::nullopt;
}
void RankLink::send_item(int, std::size_t) {}
void RankLink::send_stop(int) {}
std::optional<std::size_t> RankLink::report_and_wait(const std::string&) {
  return std::nullopt;
}

}  // namespace tripack
