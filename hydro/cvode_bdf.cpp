// CVODE BDF wrapper: every SUNDIALS call checked and reported by name (hydro/sundials_handles.hpp).
#include "hydro/cvode_bdf.hpp"

#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_band.h>
#include <sunmatrix/sunmatrix_band.h>

#include <algorithm>
#include <stdexcept>

#include "common/interrupt.hpp"

namespace coldblast::hydro {

namespace sh = sundials_handles;

namespace {

/// The banded LU of CVODE's Newton matrix A = I - γJ, equilibrated by the error weights w:
/// factors Â = W A W⁻¹ (W = diag w) and solves A x = b as x = W⁻¹ Â⁻¹ (W b). The result is
/// mathematically the same; what changes is the partial pivoting, which compares |A_ij| down a column
/// of rows in different units (cell mass ~ n∞ R^d, energy ~ E, momentum ~ √(M E)). Unscaled, the mass
/// rows win the pivots once n∞ R^d / E is large, and the LU loses the small energies (cold cells ahead of
/// the shock, 10⁻⁶ of the shocked ones): beyond R/λ ≈ 1e9 in 3D (mass/energy ≈ 1e27) the Newton
/// iterates went wrong by factors 1e3 in those cells and the step collapsed to h/t ≈ 1e-12 (docs/hydro.md,
/// "Time integration"). In the weighted variables Â is dimensionless and the pivots do not drift with R/λ.
struct EquilibratedBand {
  SUNLinearSolver band = nullptr;  // SUNLinSol_Band, factors and solves in place
  N_Vector weights = nullptr, scaled = nullptr;
  void* cvode = nullptr;  // for CVodeGetErrWeights at each setup
};

EquilibratedBand& content(SUNLinearSolver solver) {
  return *static_cast<EquilibratedBand*>(solver->content);
}

int equilibrated_setup(SUNLinearSolver solver, SUNMatrix A) {
  EquilibratedBand& self = content(solver);
  if (CVodeGetErrWeights(self.cvode, self.weights) != CV_SUCCESS) return SUNLS_PACKAGE_FAIL_UNREC;
  const double* w = N_VGetArrayPointer(self.weights);
  const sunindextype n = SUNBandMatrix_Columns(A), upper = SUNBandMatrix_UpperBandwidth(A),
                     lower = SUNBandMatrix_LowerBandwidth(A);
  for (sunindextype j = 0; j < n; ++j) {
    double* column = SUNBandMatrix_Column(A, j);  // column[i - j] = A_ij
    for (sunindextype i = std::max<sunindextype>(0, j - upper); i <= std::min<sunindextype>(n - 1, j + lower); ++i)
      column[i - j] *= w[i] / w[j];
  }
  return SUNLinSolSetup(self.band, A);
}

int equilibrated_solve(SUNLinearSolver solver, SUNMatrix A, N_Vector x, N_Vector b, realtype tolerance) {
  EquilibratedBand& self = content(solver);
  N_VProd(self.weights, b, self.scaled);
  const int flag = SUNLinSolSolve(self.band, A, x, self.scaled, tolerance);
  N_VDiv(x, self.weights, x);
  return flag;
}

int equilibrated_free(SUNLinearSolver solver) {
  if (solver == nullptr) return SUNLS_SUCCESS;
  if (solver->content) {
    EquilibratedBand* self = static_cast<EquilibratedBand*>(solver->content);
    SUNLinSolFree(self->band);
    N_VDestroy(self->weights);
    N_VDestroy(self->scaled);
    delete self;
    solver->content = nullptr;
  }
  SUNLinSolFreeEmpty(solver);
  return SUNLS_SUCCESS;
}

/// A direct linear solver for CVODE: SUNLinSol_Band on the error-weight-equilibrated Newton matrix.
SUNLinearSolver equilibrated_band_solver(N_Vector y, SUNMatrix A, void* cvode, SUNContext context) {
  SUNLinearSolver solver = sh::check_created(SUNLinSolNewEmpty(context), "SUNLinSolNewEmpty");
  auto* self = new EquilibratedBand;
  solver->content = self;
  solver->ops->gettype = [](SUNLinearSolver) { return SUNLINEARSOLVER_DIRECT; };
  solver->ops->getid = [](SUNLinearSolver) { return SUNLINEARSOLVER_CUSTOM; };
  solver->ops->initialize = [](SUNLinearSolver s) { return SUNLinSolInitialize(content(s).band); };
  solver->ops->setup = equilibrated_setup;
  solver->ops->solve = equilibrated_solve;
  solver->ops->lastflag = [](SUNLinearSolver s) { return SUNLinSolLastFlag(content(s).band); };
  solver->ops->free = equilibrated_free;
  self->cvode = cvode;
  self->weights = N_VClone(y);
  self->scaled = N_VClone(y);
  self->band = SUNLinSol_Band(y, A, context);
  if (!self->weights || !self->scaled || !self->band) {
    equilibrated_free(solver);
    throw std::runtime_error("equilibrated_band_solver: SUNDIALS allocation failed (out of memory?)");
  }
  return solver;
}

}  // namespace

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
  solver_.reset(equilibrated_band_solver(y_.get(), matrix_.get(), memory, context_));
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
