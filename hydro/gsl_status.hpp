#pragma once
// GSL error handling for hydro/: GSL's default handler aborts (GSL manual, "Error Handling"), so every
// hydro entry point that calls GSL first switches it off (main() does too) and checks each status.
#include <gsl/gsl_errno.h>

namespace coldblast::hydro::detail {

/// Turns GSL's aborting error handler off, once per process; statuses are then checked by the caller.
inline void disable_gsl_abort() {
  static const bool done = [] {
    gsl_set_error_handler_off();
    return true;
  }();
  (void)done;
}

}  // namespace coldblast::hydro::detail
