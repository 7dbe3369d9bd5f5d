#pragma once

namespace tripack {

// Debian's CHOLMOD (SuiteSparse 5, libcholmod3) runs loops of its supernodal factorization in
// OpenMP regions of a compiled-in 4 threads (CHOLMOD_OMP_NUM_THREADS). At a relax's sizes they
// cost more than they do: every region starts, wakes and joins a team of threads, and beside the
// caller's own threads they oversubscribe the cores (docs/performance.md, "CHOLMOD's OpenMP
// regions"). Called on a thread before it factorizes: every OpenMP region that thread starts
// then runs on the thread alone. The setting (OpenMP's max-active-levels) belongs to the calling
// thread; it changes no result, only who runs the loops.
void run_openmp_regions_on_this_thread();

}  // namespace tripack
