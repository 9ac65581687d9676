// Vibration modes about an equilibrium (frequencies alone: solver.hpp, natural_frequencies).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "model/model.hpp"
#include "model/state.hpp"

namespace finseg {

/// One mode of K x = w^2 M x on the free DOFs.
struct Mode {
  double frequency_hz = 0;
  Eigen::VectorXd shape;  ///< num_dofs, M-normalized: per free body (dp_W, dphi_W)
};

/// The `count` lowest modes (ascending frequency) about `state`, which should be an
/// equilibrium. Dense: limited like natural_frequencies.
std::vector<Mode> natural_modes(const Model& model, const State& state, int count);

}  // namespace finseg
