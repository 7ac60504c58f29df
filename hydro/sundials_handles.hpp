#pragma once
// RAII ownership of the SUNDIALS 6.4 objects used by hydro/ (N_Vector, SUNMatrix, SUNLinearSolver,
// CVODE memory) and the flag checks that turn every failing return into an exception naming it.
#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_linearsolver.h>
#include <sundials/sundials_matrix.h>

#include <memory>
#include <stdexcept>
#include <string>
#include <sundials/sundials_context.hpp>

namespace coldblast::hydro::sundials_handles {

struct VectorDeleter {
  void operator()(N_Vector v) const { N_VDestroy(v); }
};
struct MatrixDeleter {
  void operator()(SUNMatrix m) const { SUNMatDestroy(m); }
};
struct LinearSolverDeleter {
  void operator()(SUNLinearSolver s) const { SUNLinSolFree(s); }
};
struct CvodeDeleter {
  void operator()(void* memory) const { CVodeFree(&memory); }
};

using Vector = std::unique_ptr<std::remove_pointer_t<N_Vector>, VectorDeleter>;
using Matrix = std::unique_ptr<std::remove_pointer_t<SUNMatrix>, MatrixDeleter>;
using LinearSolver = std::unique_ptr<std::remove_pointer_t<SUNLinearSolver>, LinearSolverDeleter>;
using CvodeMemory = std::unique_ptr<void, CvodeDeleter>;

/// Throws std::runtime_error("<call> failed: <CVODE flag name> (<flag>)<context>") when flag < 0.
inline void check_cvode(int flag, const char* call, const std::string& context = "") {
  if (flag >= 0) return;
  char* name = CVodeGetReturnFlagName(flag);
  std::string message =
      std::string(call) + " failed: " + (name ? name : "unknown flag") + " (" + std::to_string(flag) + ")" + context;
  free(name);  // CVodeGetReturnFlagName allocates with malloc
  throw std::runtime_error(message);
}

/// Throws std::runtime_error naming `call` when a SUNDIALS constructor returned nullptr.
template <typename Pointer>
Pointer check_created(Pointer pointer, const char* call) {
  if (pointer == nullptr) throw std::runtime_error(std::string(call) + " returned NULL (out of memory?)");
  return pointer;
}

}  // namespace coldblast::hydro::sundials_handles
