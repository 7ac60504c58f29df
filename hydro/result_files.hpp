#pragma once
// The one schema of a Navier–Stokes result (hydro core|euler): its tables (samples, running
// exponents, profiles) as named columns and its summary as JSON. The command line's files and JSON
// and the Python module's arrays and attributes are all produced from these, so no surface maps the
// result's fields by hand (docs/cli.md "hydro core JSON", docs/python.md).
#include <filesystem>
#include <string>
#include <vector>

#include "common/output.hpp"
#include "hydro/blast_measurements.hpp"

namespace coldblast::hydro {

/// One column of a result table: its name (CSV header, Python key), values, and the significant
/// digits it is written with (17: exact round trip).
struct Column {
  std::string name;
  std::vector<double> values;
  int digits = 17;
};
using Table = std::vector<Column>;

/// samples.csv: t, R_over_lambda, R, H, H_density, n0, T0, p0, energy, mass, energy_error and the
/// prefactors (blast_measurements.hpp's NavierStokesSample), one row per sample.
Table sample_table(const NavierStokesResult& result);
/// exponents.csv: running exponents d ln X/d ln t (and d ln X/d ln(R/λ), the _in_R columns).
Table exponent_table(const NavierStokesResult& result);
/// profile.csv: r, r_over_R, density, velocity, temperature, pressure, heat_flux of one profile.
Table profile_table(const NavierStokesProfile& profile);

/// The summary: d, R/λ at the end, the final exponents beside the theory's rationals (core) or the
/// TvNS comparison (Euler), prefactors, the model solved (eos, phi, transport, start, r0/λ, the
/// start's R/λ), transport prefactors, energy errors, cells and cost. `coldblast hydro --format json`
/// prints it; the Python module's result holds it as `summary` (docs/cli.md lists the keys).
common::Json result_summary(const NavierStokesResult& result);
/// The core's final time exponents beside the paper's rationals (Table 2; R: 2/(d+2)), by
/// core_exponents' names: {"H": {"measured", "theory", "theory_rational"}, ...}; the summary's
/// "exponents" and reproduce's hydro.json.
common::Json exponents_json(const NavierStokesResult& result);

/// A table as CSV text after `header` (each line "# ..."), columns in order.
std::string table_csv(const std::string& header, const Table& table);
/// The provenance header of the result's files: the program, the command, the resolved configuration.
std::string result_file_header(const NavierStokesResult& result);
/// Writes samples.csv, exponents.csv and profile.csv (the last profile) into `directory`, atomically.
void write_result_files(const NavierStokesResult& result, const std::filesystem::path& directory);

}  // namespace coldblast::hydro
