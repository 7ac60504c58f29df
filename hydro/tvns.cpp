// TvNS blast: configuration checks, branch selection and the solution object; the two methods
// live in tvns_closed_form.cpp and tvns_ode.cpp.
#include "hydro/tvns.hpp"

#include <cmath>
#include <stdexcept>

#include "common/validate.hpp"
#include "theory/prefactors.hpp"

namespace coldblast::hydro {

void TvnsConfig::validate() const {
  common::require_integer_in_range("d", d, 1, 3, "(TvNS: planar, cylindrical or spherical)");
  if (eos == Eos::ideal) {
    if (gamma != 0.0) common::require_in_range("gamma", gamma, 1.0, 1e6, common::Bound::open, common::Bound::closed,
                                               "(0 selects 1 + 2/d)");
  } else {
    if (eos_dimension(eos) != d)
      throw std::invalid_argument("eos = " + to_string(eos) + " is for d = " +
                                  std::to_string(eos_dimension(eos)) + " only, not d = " + std::to_string(d));
    if (gamma != 0.0 && gamma != 1.0 + 2.0 / d)
      throw std::invalid_argument("gamma = " + common::format_number(gamma) +
                                  " cannot be set with eos = " + to_string(eos) + " (hard particles fix it)");
    common::require_in_range("phi", phi, 0.0, max_ambient_packing_fraction(eos), common::Bound::open,
                             common::Bound::open,
                             "for eos = " + to_string(eos) + " (post-shock phi must stay below close packing " +
                                 common::format_number(close_packing_fraction(eos)) + ")");
  }
  common::require_in_range("tolerance", tolerance, 1e-14, 1e-3, common::Bound::closed, common::Bound::closed);
}

double TvnsConfig::resolved_gamma() const {
  return (gamma == 0.0 || eos != Eos::ideal) ? 1.0 + 2.0 / d : gamma;
}

TvnsCase tvns_case(int d, double gamma) {
  if (d != 3 || gamma < 7.0) return TvnsCase::standard;
  return gamma == 7.0 ? TvnsCase::singular : TvnsCase::vacuum;
}

double amplitude_from_energy_integral(int d, double J) {
  return 4.0 * theory::unit_sphere_area(d) * J / ((d + 2.0) * (d + 2.0));
}

}  // namespace coldblast::hydro
