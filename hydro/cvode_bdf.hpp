#pragma once
// CVODE BDF integrator (SUNDIALS 6.4) with a banded difference-quotient Jacobian, a user error-weight
// function, optional positivity constraints and an optional projection, owned by RAII handles
// (hydro/sundials_handles.hpp). Used by the radial Navier–Stokes solver (hydro/navier_stokes.cpp).
#include <cvode/cvode.h>
#include <cvode/cvode_proj.h>

#include <functional>
#include <string>
#include <sundials/sundials_context.hpp>
#include <vector>

#include "hydro/sundials_handles.hpp"

namespace coldblast::hydro {

/// Work counters of one integration.
struct CvodeStatistics {
  long steps = 0, rhs_evaluations = 0, jacobian_evaluations = 0, nonlinear_iterations = 0;
  long error_test_failures = 0, nonlinear_failures = 0;
};

/// Set-up of one integration: callbacks receive `user_data`.
struct CvodeProblem {
  double t0 = 0;
  std::vector<double> y0;           ///< initial state
  std::vector<double> constraints;  ///< CVODE constraint codes per component (empty: none)
  CVRhsFn rhs = nullptr;
  CVEwtFn error_weights = nullptr;
  CVProjFn projection = nullptr;  ///< nullptr: no projection
  void* user_data = nullptr;
  int half_bandwidth = 0;  ///< Jacobian band: component i couples to i ± half_bandwidth
  long max_steps = 5000000;
  int max_error_test_failures = 20, max_convergence_failures = 50;
};

class CvodeBdf {
 public:
  /// Throws std::runtime_error naming the SUNDIALS call that failed.
  explicit CvodeBdf(const CvodeProblem& problem);
  /// Steps exactly onto t_out (CVodeSetStopTime: no interpolated output, which would not keep projected
  /// invariants) and returns the time reached; on failure throws std::runtime_error with the CVODE flag
  /// name followed by context(t).
  double advance_to(double t_out, const std::function<std::string(double)>& context);
  /// The current state (valid after construction and after each advance_to).
  const double* state() const { return N_VGetArrayPointer(y_.get()); }
  long size() const { return size_; }
  CvodeStatistics statistics() const;

 private:
  sundials::Context context_;
  long size_;
  double t_;
  sundials_handles::Vector y_, constraints_;
  sundials_handles::CvodeMemory memory_;
  sundials_handles::Matrix matrix_;
  sundials_handles::LinearSolver solver_;
};

}  // namespace coldblast::hydro
