#pragma once
// Flag-level options of `coldblast tvns` and `coldblast hydro core|euler` mapped to the solver
// configs, with the validation and messages of the command line (each error names the CLI flag,
// its value and the allowed range). Shared by cli/ and the Python module (python/), so both reject
// bad input with the same message.
#include <optional>
#include <string>
#include <vector>

#include "hydro/navier_stokes.hpp"
#include "hydro/tvns.hpp"

namespace coldblast::hydro {

/// `coldblast tvns` options (units: m = 1, k_B = 1).
struct TvnsOptions {
  int d = 2;                  ///< 1 planar, 2 cylindrical, 3 spherical
  double gamma = 0.0;         ///< ideal EOS only, [min_gamma, max_gamma]; 0 = 1 + 2/d
  std::string eos = "ideal";  ///< ideal, henderson (d = 2) or carnahan-starling (d = 3)
  double phi = 0.0;           ///< ambient packing fraction, hard-particle EOS only
  double tolerance = 1e-13;   ///< requested relative accuracy of A_d, [1e-14, 1e-3]
};
/// The validated TvnsConfig; throws std::invalid_argument naming the flag (--d, --gamma, --eos,
/// --phi, --tolerance).
TvnsConfig tvns_config(const TvnsOptions& options);

/// `coldblast tvns --at`: "0.1,0.5,1" -> {0.1, 0.5, 1}, each r/R in [0, 1] (a trailing comma is
/// allowed); throws std::invalid_argument naming --at for an empty list, a field that is not a
/// whole number, or a value outside [0, 1].
std::vector<double> parse_profile_points(const std::string& text);

/// `coldblast hydro core|euler` options.
struct HydroOptions {
  int d = 2;                              ///< 1 planar, 2 cylindrical, 3 spherical
  double until = 0.0;                     ///< R/lambda at the end; 0 = the mode's default
  int cells = 0;                          ///< finite-volume cells, [16, 100000]; 0 = the mode's default
  bool viscosity = false;                 ///< shear viscosity (core mode)
  std::optional<double> kappa_prefactor;  ///< c_kappa in [0, 1e6] (core mode); empty = Chapman-Enskog
  std::string eos = "ideal";              ///< ideal, henderson (d = 2) or carnahan-starling (d = 3)
  double phi = 0.0;                    ///< ambient packing fraction; 0 = the library's default for a hard-particle EOS
  std::string transport = "dilute";    ///< transport coefficients (hydro::transport_from_string)
  double outer_margin = 0.0;           ///< outer grid edge / R_ref, [1.05, 2]; 0 = the solver's default (1.15)
  std::string start = "self-similar";  ///< how E enters (hydro::start_from_string): self-similar or hotspot
  double r0 = 0.0;                     ///< hot-spot radius r0/lambda, > 0 with start = hotspot
};
/// The Navier–Stokes model keys of a TOML file's [hydro] table (docs/hydro.md): the same values as
/// --eos, --phi, --transport, --viscosity (a TOML boolean), --start, --r0. An unset key leaves the
/// flag's value.
struct HydroModelKeys {
  std::optional<std::string> eos;
  std::optional<double> phi;
  std::optional<std::string> transport;
  std::optional<bool> viscosity;
  std::optional<std::string> start;
  std::optional<double> r0;
};
/// Reads the [hydro] table of TOML text (no table: no keys); other tables and keys of the file (a
/// scene's) are left alone. Throws std::invalid_argument naming hydro.<key> for an unknown key or a
/// value of the wrong type, and naming `source` for a TOML syntax error.
HydroModelKeys read_hydro_model_keys(const std::string& toml_text, const std::string& source);

/// Default end of the run: R/lambda = 1e4 (core), 500 (Euler).
inline constexpr double default_core_until = 1e4;
inline constexpr double default_euler_until = 500;
/// The validated NavierStokesConfig of core (euler = false) or Euler (kappa = mu = 0) mode, with the
/// keys of `file` replacing the options' eos, phi, transport, viscosity (core mode), start and r0 (the caller drops the
/// keys whose flag was given). Throws std::invalid_argument naming the flag (--d, --cells, --until, --eos,
/// --phi, --transport, --kappa-prefactor, --start, --r0), or hydro.<key> for a value taken from the file.
NavierStokesConfig navier_stokes_config(const HydroOptions& options, bool euler, const HydroModelKeys& file = {});

}  // namespace coldblast::hydro
