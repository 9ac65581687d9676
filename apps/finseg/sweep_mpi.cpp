#include "apps/finseg/sweep_mpi.hpp"

#include <mpi.h>

#include <cstdlib>
#include <nlohmann/json.hpp>
#include <string>

namespace finseg::cli {
namespace {

// Set by Open MPI's mpirun (and PMIx / PMI launchers) in each rank's environment.
bool started_by_mpirun() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK"}) {
    if (std::getenv(v)) return true;
  }
  return false;
}

}  // namespace

SweepMpi::SweepMpi() {
  if (!started_by_mpirun()) return;
  MPI_Init(nullptr, nullptr);
  active_ = true;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

SweepMpi::~SweepMpi() {
  if (active_) MPI_Finalize();
}

std::vector<SweepCaseResult> SweepMpi::gather(const std::vector<std::size_t>& indices,
                                              const std::vector<SweepCaseResult>& mine,
                                              std::size_t cases) const {
  std::vector<SweepCaseResult> all(rank_ == 0 ? cases : 0);
  if (!active_) {
    for (std::size_t k = 0; k < indices.size(); ++k) all[indices[k]] = mine[k];
    return all;
  }
  // Each rank's results as JSON text: [[case, summary, failure], ...].
  nlohmann::json rows = nlohmann::json::array();
  for (std::size_t k = 0; k < indices.size(); ++k) {
    rows.push_back({indices[k], mine[k].summary, mine[k].failure});
  }
  const std::string text = rows.dump();
  int length = static_cast<int>(text.size());
  std::vector<int> lengths(size_), offsets(size_);
  MPI_Gather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  std::string received;
  if (rank_ == 0) {
    long total = 0;
    for (int r = 0; r < size_; ++r) offsets[r] = static_cast<int>(total), total += lengths[r];
    received.resize(total);
  }
  MPI_Gatherv(text.data(), length, MPI_CHAR, received.data(), lengths.data(), offsets.data(),
              MPI_CHAR, 0, MPI_COMM_WORLD);
  for (int r = 0; r < size_ && rank_ == 0; ++r) {
    for (const auto& row : nlohmann::json::parse(received.substr(offsets[r], lengths[r]))) {
      all.at(row[0].get<std::size_t>()) = {row[1], row[2].get<std::string>()};
    }
  }
  return all;
}

int SweepMpi::broadcast(int value) const {
  if (active_) MPI_Bcast(&value, 1, MPI_INT, 0, MPI_COMM_WORLD);
  return value;
}

void SweepMpi::abort(int code) const {
  if (active_) MPI_Abort(MPI_COMM_WORLD, code);
  std::exit(code);
}

}  // namespace finseg::cli
