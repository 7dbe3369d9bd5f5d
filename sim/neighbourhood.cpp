// The out-of-line parts of sim/neighbourhood.hpp: the vectorised pair_times kernel (its own
// translation unit because target_clones needs a non-inline definition; CMakeLists.txt compiles
// it with -fno-math-errno -fno-trapping-math, without which it does not vectorise) and the rare
// neighbourhood operations (building all lists, growing their storage).
#include "sim/neighbourhood.hpp"

// ThreadSanitizer instruments the ifunc resolver that target_clones generates; the dynamic
// loader runs that resolver before the TSan runtime is initialised, and the program crashes at
// start (GCC 12 and clang 14; llvm/llvm-project#163369). A TSan build (scripts/sanitize.sh)
// compiles the default version only: the kernel touches no shared state, so nothing is lost.
#if defined(__SANITIZE_THREAD__)
#define TRIPACK_PAIR_TIMES_CLONES
#elif defined(__has_feature)
#if __has_feature(thread_sanitizer)
#define TRIPACK_PAIR_TIMES_CLONES
#endif
#endif
#ifndef TRIPACK_PAIR_TIMES_CLONES
#define TRIPACK_PAIR_TIMES_CLONES __attribute__((target_clones("avx2", "default")))
#endif

namespace tripack::sim_detail {

TRIPACK_PAIR_TIMES_CLONES void pair_times(int m, const Disk* __restrict disks,
                                          const int* __restrict list, Vec2 xi, Vec2 vi, double now,
                                          double D, double g, double* __restrict t) {
  for (int k = 0; k < m; ++k) {
    const Disk& dj = disks[list[k]];
    const double px = dj.x0.x + dj.v.x * now - xi.x;
    const double py = dj.x0.y + dj.v.y * now - xi.y;
    const double ux = dj.v.x - vi.x, uy = dj.v.y - vi.y;
    const double b = px * ux + py * uy - g * D;
    const double a = ux * ux + uy * uy - g * g;
    const double c0 = px * px + py * py - D * D;
    // c <= 0: touching (or rounding overlap); approaching, the root is then exactly 0 (now).
    const double c = std::max(c0, 0.0);
    const double disc = b * b - a * c;
    const double root = std::sqrt(std::max(disc, 0.0));
    // Approaching (b < 0): c / (root - b). Receding but growth outruns it (a < 0):
    // (b + root) / -a. Otherwise (receding faster than growth, or a miss: disc < 0) never.
    // Every operation runs on every lane; only values are selected (what lets it vectorise).
    const bool approaching = b < 0;
    const double num = approaching ? c : b + root;
    const double den = approaching ? root - b : -a;
    const double q = num / den;
    const bool hit = (approaching | (a < 0)) & (disc >= 0);
    t[k] = hit ? q : kInf;
  }
}

// A grid over the bounding box indexes the anchors; cell side >= the largest neighbourhood
// diameter (the largest disk diameter `diam_max` plus twice the skin), so overlapping
// neighbourhoods are anchored in adjacent cells.
void Neighbourhoods::build(const std::vector<Disk>& disks, double now, double D, double diam_max) {
  n_ = int(disks.size());
  diam_max_ = diam_max + 1e-300;
  skin_ = kSkin * diam_max_;
  const double cell_size = (diam_max_ + 2 * skin_) * (1 + 1e-9);
  mx_ = std::max(1, int(1.0 / cell_size));
  my_ = std::max(1, int(kH / cell_size));
  wx_ = 1.0 / mx_;
  wy_ = kH / my_;
  cell_count_.assign(std::size_t(mx_) * std::size_t(my_), 0);
  cell_cap_ = 8;
  cell_list_.assign(cell_count_.size() * std::size_t(cell_cap_), 0);
  nbr_cap_ = 16;
  nbr_count_.assign(std::size_t(n_), 0);
  nbr_.assign(std::size_t(n_) * std::size_t(nbr_cap_), 0);
  batch_.assign(std::size_t(nbr_cap_), 0.0);
  hood_.resize(std::size_t(n_));
  for (int i = 0; i < n_; ++i) {
    const Disk& d = disks[std::size_t(i)];
    set_neighbourhood(i, d.x0 + d.v * now, D);
    cell_insert(i);
  }
  for (int i = 0; i < n_; ++i)
    for_each_overlapping(i, [&](int j) {
      if (j > i) add_neighbours(i, j);
    });
}

void Neighbourhoods::grow_neighbour_lists() {
  const int cap = 2 * nbr_cap_;
  std::vector<int> list(std::size_t(n_) * std::size_t(cap));
  for (int i = 0; i < n_; ++i)
    std::copy_n(neighbours(i), nbr_count_[std::size_t(i)],
                list.begin() + std::ptrdiff_t(std::size_t(i) * std::size_t(cap)));
  nbr_.swap(list);
  nbr_cap_ = cap;
  batch_.assign(std::size_t(nbr_cap_), 0.0);
}

void Neighbourhoods::grow_cells() {
  const int cap = 2 * cell_cap_;
  std::vector<int> list(cell_count_.size() * std::size_t(cap));
  for (std::size_t c = 0; c < cell_count_.size(); ++c)
    std::copy_n(cell_list_.begin() + std::ptrdiff_t(c * std::size_t(cell_cap_)), cell_count_[c],
                list.begin() + std::ptrdiff_t(c * std::size_t(cap)));
  cell_list_.swap(list);
  cell_cap_ = cap;
}

}  // namespace tripack::sim_detail
