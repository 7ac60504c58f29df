// CVODE BDF wrapper: every SUNDIALS call checked and reported by name (hydro/sundials_handles.hpp).
#include "hydro/cvode_bdf.hpp"

#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_band.h>
#include <sunmatrix/sunmatrix_band.h>

#include <algorithm>

#include "common/interrupt.hpp"

namespace coldblast::hydro {

namespace sh = sundials_handles;

CvodeBdf::CvodeBdf(const CvodeProblem& problem) : size_(static_cast<long>(problem.y0.size())), t_(problem.t0) {
  y_.reset(sh::check_created(N_VNew_Serial(size_, context_), "N_VNew_Serial"));
  std::copy(problem.y0.begin(), problem.y0.end(), N_VGetArrayPointer(y_.get()));
  memory_.reset(sh::check_created(CVodeCreate(CV_BDF, context_), "CVodeCreate"));
  void* memory = memory_.get();
  sh::check_cvode(CVodeInit(memory, problem.rhs, problem.t0, y_.get()), "CVodeInit");
  sh::check_cvode(CVodeWFtolerances(memory, problem.error_weights), "CVodeWFtolerances");
  sh::check_cvode(CVodeSetUserData(memory, problem.user_data), "CVodeSetUserData");
  if (!problem.constraints.empty()) {
    constraints_.reset(sh::check_created(N_VNew_Serial(size_, context_), "N_VNew_Serial"));
    std::copy(problem.constraints.begin(), problem.constraints.end(), N_VGetArrayPointer(constraints_.get()));
    sh::check_cvode(CVodeSetConstraints(memory, constraints_.get()), "CVodeSetConstraints");
  }
  if (problem.projection) sh::check_cvode(CVodeSetProjFn(memory, problem.projection), "CVodeSetProjFn");
  sh::check_cvode(CVodeSetMaxNumSteps(memory, problem.max_steps), "CVodeSetMaxNumSteps");
  sh::check_cvode(CVodeSetMaxErrTestFails(memory, problem.max_error_test_failures), "CVodeSetMaxErrTestFails");
  sh::check_cvode(CVodeSetMaxConvFails(memory, problem.max_convergence_failures), "CVodeSetMaxConvFails");
  const int band = problem.half_bandwidth;
  matrix_.reset(sh::check_created(SUNBandMatrix(size_, band, band, context_), "SUNBandMatrix"));
  solver_.reset(sh::check_created(SUNLinSol_Band(y_.get(), matrix_.get(), context_), "SUNLinSol_Band"));
  sh::check_cvode(CVodeSetLinearSolver(memory, solver_.get(), matrix_.get()), "CVodeSetLinearSolver");
}

double CvodeBdf::advance_to(double t_out, const std::function<std::string(double)>& context) {
  sh::check_cvode(CVodeSetStopTime(memory_.get(), t_out), "CVodeSetStopTime");
  const int flag = CVode(memory_.get(), t_out, y_.get(), &t_, CV_NORMAL);
  if (flag < 0) {
    common::throw_if_stop_requested();  // the RHS refused to run on a stop request
    sh::check_cvode(flag, "CVode", context ? context(t_) : std::string());
  }
  return t_;
}

CvodeStatistics CvodeBdf::statistics() const {
  void* memory = memory_.get();
  CvodeStatistics s;
  long value = 0;
  sh::check_cvode(CVodeGetNumSteps(memory, &value), "CVodeGetNumSteps");
  s.steps = value;
  sh::check_cvode(CVodeGetNumRhsEvals(memory, &value), "CVodeGetNumRhsEvals");
  s.rhs_evaluations = value;
  sh::check_cvode(CVodeGetNumLinRhsEvals(memory, &value), "CVodeGetNumLinRhsEvals");
  s.rhs_evaluations += value;
  sh::check_cvode(CVodeGetNumJacEvals(memory, &value), "CVodeGetNumJacEvals");
  s.jacobian_evaluations = value;
  sh::check_cvode(CVodeGetNumNonlinSolvIters(memory, &value), "CVodeGetNumNonlinSolvIters");
  s.nonlinear_iterations = value;
  sh::check_cvode(CVodeGetNumErrTestFails(memory, &value), "CVodeGetNumErrTestFails");
  s.error_test_failures = value;
  sh::check_cvode(CVodeGetNumNonlinSolvConvFails(memory, &value), "CVodeGetNumNonlinSolvConvFails");
  s.nonlinear_failures = value;
  return s;
}

}  // namespace coldblast::hydro
