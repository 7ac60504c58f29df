#include "hydro/options.hpp"

#include <toml++/toml.h>

#include <cstdlib>
#include <sstream>
#include <stdexcept>

#include "common/input.hpp"
#include "common/validate.hpp"

namespace coldblast::hydro {

namespace {
const common::FieldNames tvns_flags = {
    {"d", "--d"}, {"gamma", "--gamma"}, {"eos", "--eos"}, {"phi", "--phi"}, {"tolerance", "--tolerance"}};
const common::FieldNames hydro_flags = {{"d", "--d"},
                                        {"cells", "--cells"},
                                        {"until_R_over_lambda", "--until"},
                                        {"eos", "--eos"},
                                        {"phi", "--phi"},
                                        {"transport", "--transport"},
                                        {"kappa_prefactor", "--kappa-prefactor"},
                                        {"outer_margin", "--outer-margin"},
                                        {"start", "--start"},
                                        {"r0_over_lambda", "--r0"}};
}  // namespace

std::vector<double> parse_profile_points(const std::string& text) {
  const std::string expected = " (expected r/R values in [0, 1], e.g. 0.1,0.5,1)";
  std::vector<std::string> items = common::split_fields(text);
  if (!items.empty() && items.back().empty()) items.pop_back();  // "0.1,0.5,"
  std::vector<double> values;
  for (const std::string& item : items) {
    // strtod, not stod: an underflow such as 1e-400 reads as the nearest double (0 or subnormal)
    // instead of throwing; overflow, NaN and infinity fail the range check below.
    char* end = nullptr;
    const double value = item.empty() ? 0.0 : std::strtod(item.c_str(), &end);
    if (item.empty() || end != item.c_str() + item.size())
      throw std::invalid_argument("--at = " + text + ": '" + item + "' is not a number" + expected);
    common::require_in_range("--at r/R", value, 0.0, 1.0, common::Bound::closed, common::Bound::closed);
    values.push_back(value);
  }
  if (values.empty()) throw std::invalid_argument("--at is empty" + expected);
  return values;
}

TvnsConfig tvns_config(const TvnsOptions& options) {
  // TvnsConfig::validate holds the rules; the flags only rename its fields.
  return common::with_field_names(tvns_flags, [&] {
    const TvnsConfig config{options.d, options.gamma, eos_from_string(options.eos, "eos"), options.phi,
                            options.tolerance};
    config.validate();
    return config;
  });
}

HydroModelKeys read_hydro_model_keys(const std::string& toml_text, const std::string& source) {
  toml::table root;
  try {
    root = toml::parse(std::string_view(toml_text), std::string_view(source));
  } catch (const toml::parse_error& e) {
    std::ostringstream message;
    message << source << ": " << e.description() << " (line " << e.source().begin.line << ")";
    throw std::invalid_argument(message.str());
  }
  HydroModelKeys keys;
  const toml::node_view<toml::node> node = root["hydro"];
  if (!node) return keys;
  const toml::table* table = node.as_table();
  if (!table) throw std::invalid_argument("hydro in " + source + " must be a table ([hydro])");
  for (auto&& [key_view, node_value] : *table) {
    const std::string key(key_view.str());
    const toml::node& value = node_value;  // a lambda may not capture a structured binding (C++17; clang)
    const auto text = [&] {
      if (const auto* s = value.as_string()) return s->get();
      throw std::invalid_argument("hydro." + key + " in " + source + " must be a string");
    };
    const auto number = [&] {
      if (const std::optional<double> x = value.value<double>()) return *x;
      throw std::invalid_argument("hydro." + key + " in " + source + " must be a number");
    };
    if (key == "eos")
      keys.eos = text();
    else if (key == "transport")
      keys.transport = text();
    else if (key == "start")
      keys.start = text();
    else if (key == "viscosity") {
      if (const std::optional<bool> on = value.value<bool>(); on && value.is_boolean())
        keys.viscosity = *on;
      else
        throw std::invalid_argument("hydro.viscosity in " + source + " must be true or false");
    } else if (key == "phi")
      keys.phi = number();
    else if (key == "r0")
      keys.r0 = number();
    else
      throw std::invalid_argument("unknown key hydro." + key + " in " + source +
                                  " (allowed: eos, phi, transport, viscosity, start, r0)");
  }
  return keys;
}

NavierStokesConfig navier_stokes_config(const HydroOptions& flags, bool euler, const HydroModelKeys& file) {
  // The file's keys replace the flags' values, and its key names replace theirs in messages.
  HydroOptions options = flags;
  common::FieldNames names = hydro_flags;
  const auto from_file = [&](const char* key) {  // the field of key r0 is r0_over_lambda
    for (auto& entry : names)
      if (entry.second == std::string("--") + key) entry.second = std::string("hydro.") + key;
  };
  if (file.eos) options.eos = *file.eos, from_file("eos");
  if (file.phi) options.phi = *file.phi, from_file("phi");
  if (file.transport) options.transport = *file.transport, from_file("transport");
  if (file.viscosity) options.viscosity = *file.viscosity;
  if (file.start) options.start = *file.start, from_file("start");
  if (file.r0) options.r0 = *file.r0, from_file("r0");
  // NavierStokesConfig::validate holds the rules; the flags and keys only rename its fields.
  return common::with_field_names(names, [&] {
    NavierStokesConfig config;
    config.physics.d = options.d;
    config.numerics.cells = options.cells == 0 ? (euler ? default_euler_cells : default_core_cells) : options.cells;
    config.until_R_over_lambda =
        options.until == 0 ? (euler ? default_euler_until : default_core_until) : options.until;
    config.physics.eos = eos_from_string(options.eos, "eos");
    config.physics.phi = options.phi;
    config.physics.transport = transport_from_string(options.transport, "transport");
    if (options.outer_margin != 0.0) config.numerics.outer_margin = options.outer_margin;
    config.physics.start = start_from_string(options.start, "start");
    config.physics.r0_over_lambda = options.r0;
    if (euler) {
      config.physics.heat_conduction = false;
      config.physics.viscosity = false;
    } else {
      config.physics.kappa_prefactor = options.kappa_prefactor;
      config.physics.viscosity = options.viscosity;
    }
    config.validate();
    return config;
  });
}

}  // namespace coldblast::hydro
