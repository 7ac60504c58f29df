#pragma once
// The delete-one-block jackknife (Quenouille 1956; Efron & Tibshirani, "An Introduction to the
// Bootstrap", 1993, Sec. 11.2): the one home of every error bar computed from blocks of MD
// realizations or tracer trajectories (compare's running exponents, fits and amplitudes; the
// tracer's prefactors and moments). Statistics, not physics: it lives in common/ so that both
// compare/ and kinetic/ call it (cmake/check_layering.cmake).
#include <cstddef>
#include <functional>
#include <vector>

namespace coldblast::common {

/// An estimator θ (P values) on blocks of samples, with its jackknife variances: with θ_-b the
/// estimator on every block but b and θ̄ their mean over the B blocks,
///   cov_ij = (B-1)/B Σ_b (θ_-b,i − θ̄_i)(θ_-b,j − θ̄_j)   (Efron & Tibshirani Eq. (11.5)).
struct Jackknife {
  std::vector<double> value;       ///< θ on all blocks
  std::vector<double> variance;    ///< cov_ii; NaN with fewer than 2 blocks
  std::vector<double> covariance;  ///< cov_ij row-major (P×P), only with JackknifeCovariance::full
  int blocks = 0;                  ///< B
  /// √variance[i], the standard error of value[i].
  double error(std::size_t i) const;
  /// cov_ij; needs JackknifeCovariance::full.
  double covariance_at(std::size_t i, std::size_t j) const;
};

/// Whether block_jackknife computes the full covariance matrix or only its diagonal.
enum class JackknifeCovariance { diagonal, full };

/// The argument of the estimator for the estimate on all blocks.
inline constexpr long all_blocks = -1;

/// Applies `estimate` to all blocks (left_out = all_blocks) and to each leave-one-block-out sample
/// (left_out = 0 .. blocks−1, in this order); every call returns the same number of values. With
/// fewer than 2 blocks the value is computed and the variances are NaN (callers that need an error
/// bar throw first, naming what is missing).
Jackknife block_jackknife(long blocks, const std::function<std::vector<double>(long left_out)>& estimate,
                          JackknifeCovariance covariance = JackknifeCovariance::diagonal);

}  // namespace coldblast::common
