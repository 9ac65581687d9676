// Open MPI for `finseg sweep` (docs/sweep.md, "Across machines"): when the program was started
// by mpirun, each rank runs the cases i with i % ranks == rank and rank 0 gathers the rows.
// Only the program links MPI; the library stays free of it.
#pragma once

#include <cstddef>
#include <vector>

#include "sweep/sweep_table.hpp"

namespace finseg::cli {

/// MPI for the lifetime of a sweep: initialised only when the environment shows the process
/// was started by mpirun (else one rank of one, no MPI call made), finalised on destruction.
class SweepMpi {
 public:
  SweepMpi();
  ~SweepMpi();
  SweepMpi(const SweepMpi&) = delete;
  SweepMpi& operator=(const SweepMpi&) = delete;

  bool active() const { return active_; }
  int rank() const { return rank_; }
  int size() const { return size_; }

  /// Rank 0 gets every case's result (`cases` of them, in case order) from the ranks' own
  /// results (`mine[k]` is case `indices[k]`); the other ranks get an empty list.
  std::vector<SweepCaseResult> gather(const std::vector<std::size_t>& indices,
                                      const std::vector<SweepCaseResult>& mine,
                                      std::size_t cases) const;

  /// Rank 0's value on every rank.
  int broadcast(int value) const;

  /// Ends every rank at once (a failure on one rank that the others cannot see).
  [[noreturn]] void abort(int code) const;

 private:
  bool active_ = false;
  int rank_ = 0, size_ = 1;
};

}  // namespace finseg::cli
