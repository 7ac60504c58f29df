#pragma once
// Exponents of A(t) ∝ t^alpha from an ensemble of realizations (paper Sec. V): running exponents
// alpha(t_k) = ln(A_{k+1}/A_k)/ln(t_{k+1}/t_k) (= 4[ln A(2^{1/4} t) - ln A(t)]/ln 2 on the paper's
// grid) and least-squares exponents over a window, all with delete-one-block jackknife errors.
// Errors come from the realizations themselves, never from the scatter of the curve, because
// successive times of one realization are correlated.
#include <Eigen/Dense>
#include <functional>
#include <vector>

#include "common/jackknife.hpp"
#include "compare/run_data.hpp"

namespace coldblast::compare {

/// The blocks holding at least one realization: the samples a jackknife leaves out one at a time.
int nonempty_blocks(const BlockSeries& series);

/// common::block_jackknife over the series' non-empty blocks: `estimator` maps ensemble values A(t_k)
/// (all blocks, or all but one) to a parameter vector. Throws std::invalid_argument naming the
/// observable with fewer than 2 non-empty blocks.
common::Jackknife jackknife(const BlockSeries& series,
                            const std::function<std::vector<double>(const std::vector<double>&)>& estimator,
                            common::JackknifeCovariance covariance = common::JackknifeCovariance::diagonal);

/// One running exponent between two successive recording times.
struct RunningExponent {
  double t = 0, t_next = 0;  ///< the pair of times (the paper quotes alpha at t)
  double alpha = 0, error = 0;
};

/// Running exponents at every successive pair of recording times; jackknife errors.
std::vector<RunningExponent> running_exponents(const BlockSeries& series);

/// Least-squares fit of ln A = ln c + alpha ln t over t in [t_first, t_last].
struct PowerLawFit {
  double exponent = 0, exponent_error = 0;
  double log_amplitude = 0, log_amplitude_error = 0;
  Eigen::Matrix2d covariance = Eigen::Matrix2d::Zero();  ///< of (ln c, alpha), jackknife
  double t_first = 0, t_last = 0;
  int points = 0, blocks = 0;
};

/// The recording times inside [t_first, t_last] (a window fit needs at least 2).
int recorded_times_in(const BlockSeries& series, double t_first, double t_last);

/// Fit over the recording times inside [t_first, t_last]; needs >= 2 times and >= 2 blocks,
/// otherwise throws std::invalid_argument saying what is missing.
PowerLawFit fit_power_law(const BlockSeries& series, double t_first, double t_last);

}  // namespace coldblast::compare
