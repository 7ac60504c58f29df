#include "run/scene_file.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "common/input.hpp"
#include "common/validate.hpp"
#include "theory/observables.hpp"

namespace coldblast::run {

namespace {
using common::format_number;
using common::require_integer_in_range;
using md::BlastConfig;
using md::ImpurityConfig;

std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (const char ch : s) {
    if (ch == '"' || ch == '\\') out += '\\';
    out += ch;
  }
  return out + "\"";
}

/// A TOML array of strings: ["a", "b"].
std::string string_array(const std::vector<std::string>& items) {
  std::string out = "[";
  for (std::size_t i = 0; i < items.size(); ++i) out += (i ? ", " : "") + quoted(items[i]);
  return out + "]";
}

/// The embedded default scene; its observables are the catalogue's (theory::is_default_scene_observable).
std::string make_default_scene() {
  return R"(# Embedded default scene: a small 2D blast (a few seconds on one core).
name = "default"
d = 2
n = 0.15
a = 0.5
E = 10.0
A_d = 0.0            # 0: not given (hydro's hard-particle TvNS A_d(phi): hydro::md_amplitude)
t_min = 1.0
t_max = 200.0
realizations = 32
seed = 1
block_size = 16
observables = )" +
         string_array(theory::observable_names(theory::is_default_scene_observable)) + R"(
box_margin = 3.0     # small blasts run ahead of Eq. (1) early on (docs/md-output.md)

[impurities]
count = 4
mass = 1.0
radius = 0.0         # 0: the host radius a
)";
}

double number(const toml::node& node, const std::string& key) {
  // + 0.0 turns -0.0 into +0.0: -0 would be written back by to_toml() as the integer -0, which reads
  // as +0, so a scene would not survive its own round trip (checkpoints and merges compare that text).
  if (auto v = node.value<double>()) return *v + 0.0;
  throw std::invalid_argument("scene key " + key + " must be a number");
}
long long integer(const toml::node& node, const std::string& key) {
  if (node.is_integer()) return *node.value<long long>();
  if (auto v = node.value<double>(); v && std::floor(*v) == *v && std::abs(*v) < 9e15)
    return static_cast<long long>(*v);
  throw std::invalid_argument("scene key " + key + " must be an integer");
}
/// integer() as an int, clamped to [lo, hi] so that an out-of-range value still reaches validate(),
/// which names the key and its allowed range (a plain cast would wrap it into range).
int clamped_int(const toml::node& node, const std::string& key, long long lo, long long hi) {
  return static_cast<int>(std::clamp<long long>(integer(node, key), lo, hi));
}
std::string text(const toml::node& node, const std::string& key) {
  if (auto v = node.value<std::string>()) return *v;
  throw std::invalid_argument("scene key " + key + " must be a string");
}
bool boolean(const toml::node& node, const std::string& key) {
  // is_boolean first: toml++'s value<bool>() converts an integer (2 would read as true).
  if (node.is_boolean()) return *node.value<bool>();
  throw std::invalid_argument("scene key " + key + " must be true or false");
}

void merge_into(toml::table& base, const toml::table& extra) {
  for (auto&& [key, value] : extra) {
    if (value.is_table() && base.contains(key) && base[key].is_table()) {
      merge_into(*base[key].as_table(), *value.as_table());
    } else {
      base.insert_or_assign(key, value);
    }
  }
}

toml::table parse_table(const std::string& text_in, const std::string& source) {
  try {
    return toml::parse(std::string_view(text_in), std::string_view(source));
  } catch (const toml::parse_error& e) {
    std::ostringstream message;
    message << source << ": " << e.description() << " (line " << e.source().begin.line << ")";
    throw std::invalid_argument(message.str());
  }
}

void apply_impurities(const toml::table& table, ImpurityConfig& impurities) {
  for (auto&& [key_view, node] : table) {
    const std::string key(key_view.str());
    if (key == "count")
      impurities.count = clamped_int(node, "impurities.count", INT32_MIN, INT32_MAX);
    else if (key == "mass")
      impurities.mass = number(node, "impurities.mass");
    else if (key == "radius")
      impurities.radius = number(node, "impurities.radius");
    else if (key == "recollide")
      impurities.recollide = boolean(node, "impurities.recollide");
    else
      throw std::invalid_argument("unknown scene key impurities." + key + " (allowed: count, mass, radius, recollide)");
  }
}

void apply_start(const toml::table& table, md::StartConfig& start) {
  for (auto&& [key_view, node] : table) {
    const std::string key(key_view.str());
    if (key == "kind")
      start.kind = md::start_kind_from_name(text(node, "start.kind"));
    else if (key == "r0")
      start.r0 = number(node, "start.r0");
    else
      throw std::invalid_argument("unknown scene key start." + key + " (allowed: kind, r0)");
  }
}

/// The scene's physics keys (false: `key` is not one of them).
bool apply_physics_key(const std::string& key, const toml::node& node, BlastConfig& c) {
  if (key == "name")
    c.name = text(node, key);
  else if (key == "d")
    c.d = clamped_int(node, key, -1000, 1000);
  else if (key == "n")
    c.n = number(node, key);
  else if (key == "a")
    c.a = number(node, key);
  else if (key == "E")
    c.E = number(node, key);
  else if (key == "A_d")
    c.A_d = number(node, key);
  else if (key == "t_min")
    c.t_min = number(node, key);
  else if (key == "t_max")
    c.t_max = number(node, key);
  else
    return false;
  return true;
}

/// The ensemble's, the engine's and the snapshots' scalar keys (false: `key` is not one of them).
bool apply_run_key(const std::string& key, const toml::node& node, BlastConfig& c) {
  if (key == "realizations") {
    c.realizations = integer(node, key);
  } else if (key == "seed") {
    const long long s = integer(node, key);
    require_integer_in_range("seed", s, 0, std::numeric_limits<long long>::max());
    c.seed = static_cast<std::uint64_t>(s);
  } else if (key == "block_size") {
    c.block_size = clamped_int(node, key, -1, INT32_MAX);
  } else if (key == "box_margin") {
    c.box_margin = number(node, key);
  } else if (key == "region_growths") {
    c.region_growths = clamped_int(node, key, -1, 1000000);
  } else if (key == "cell_width") {
    c.cell_width = number(node, key);
  } else if (key == "queue") {
    c.queue = text(node, key);
  } else if (key == "profile_bins") {
    c.profile_bins = clamped_int(node, key, -1, 1000000);
  } else if (key == "p_imp_bins") {
    c.p_imp_bins = clamped_int(node, key, -1, 1000000);
  } else if (key == "overlap_check") {
    c.overlap_check = boolean(node, key);
  } else if (key == "snapshot_particles") {
    c.snapshot_particles = text(node, key);
  } else if (key == "snapshot_margin") {
    c.snapshot_margin = number(node, key);
  } else if (key == "snapshot_stride") {
    c.snapshot_stride = clamped_int(node, key, -1, INT32_MAX);
  } else {
    return false;
  }
  return true;
}

/// The array keys (false: `key` is not one of them).
bool apply_list_key(const std::string& key, const toml::node& node, BlastConfig& c) {
  if (key != "observables" && key != "snapshot_times" && key != "snapshot_fractions" && key != "snapshot_realizations")
    return false;
  const toml::array* array = node.as_array();
  if (!array) throw std::invalid_argument("scene key " + key + " must be an array");
  if (key == "observables") {
    c.observables.clear();
    for (auto&& item : *array) c.observables.push_back(text(item, key));
  } else if (key == "snapshot_realizations") {
    c.snapshot_realizations.clear();
    for (auto&& item : *array) c.snapshot_realizations.push_back(integer(item, key));
  } else {
    std::vector<double>& list = key == "snapshot_times" ? c.snapshot_times : c.snapshot_fractions;
    list.clear();
    for (auto&& item : *array) list.push_back(number(item, key));
  }
  return true;
}

/// The tables [impurities], [start] and [hydro] (false: `key` is not one of them).
bool apply_section(const std::string& key, const toml::node& node, BlastConfig& c) {
  if (key == "impurities") {
    if (!node.is_table()) throw std::invalid_argument("scene key impurities must be a table");
    apply_impurities(*node.as_table(), c.impurities);
  } else if (key == "start") {
    if (!node.is_table()) throw std::invalid_argument("scene key start must be a table ([start])");
    apply_start(*node.as_table(), c.start);
  } else if (key == "hydro") {
    // The continuum model of `hydro core|euler --config` and `compare --hydro-config`
    // (hydro::read_hydro_model_keys, docs/hydro.md); not part of the MD.
    if (!node.is_table()) throw std::invalid_argument("scene key hydro must be a table ([hydro])");
  } else {
    return false;
  }
  return true;
}

BlastConfig config_from_table(const toml::table& table) {
  BlastConfig c;
  for (auto&& [key_view, node] : table) {
    const std::string key(key_view.str());
    if (!apply_physics_key(key, node, c) && !apply_run_key(key, node, c) && !apply_list_key(key, node, c) &&
        !apply_section(key, node, c))
      throw std::invalid_argument(
          "unknown scene key " + key +
          " (allowed: name, d, n, a, E, A_d, impurities.{count,mass,radius,recollide}, start.{kind,r0}, t_min, t_max, "
          "realizations, "
          "seed, "
          "block_size, observables, box_margin, region_growths, cell_width, queue, snapshot_times, snapshot_fractions, "
          "snapshot_particles, snapshot_margin, snapshot_stride, snapshot_realizations, profile_bins, p_imp_bins, "
          "overlap_check, [hydro])");
  }
  return c;
}

}  // namespace

const std::string& default_scene_toml() {
  static const std::string text = make_default_scene();
  return text;
}

namespace {
/// The scene's table with the "key=value" overrides (--set) merged in; `drop_snapshots` removes
/// the text's snapshot keys first (an override of them still applies).
toml::table scene_table(const std::string& toml_text, const std::vector<std::string>& overrides,
                        const std::string& source, bool drop_snapshots) {
  toml::table table = parse_table(toml_text, source);
  if (drop_snapshots)
    for (const char* key : {"snapshot_times", "snapshot_fractions", "snapshot_particles", "snapshot_margin",
                            "snapshot_stride", "snapshot_realizations"})
      table.erase(key);
  for (const std::string& assignment : overrides) {
    const auto eq = assignment.find('=');
    if (eq == std::string::npos || eq == 0)
      throw std::invalid_argument("--set " + assignment + " is not of the form key=value");
    const std::string key = assignment.substr(0, eq), value = assignment.substr(eq + 1);
    toml::table extra;
    try {
      extra = toml::parse(std::string_view(key + " = " + value), std::string_view("--set"));
    } catch (const toml::parse_error&) {
      extra = parse_table(key + " = " + quoted(value), "--set " + assignment);  // bare words are strings
    }
    merge_into(table, extra);
  }
  return table;
}
}  // namespace

BlastConfig parse_scene(const std::string& toml_text, const std::vector<std::string>& overrides,
                        const std::string& source) {
  BlastConfig config = config_from_table(scene_table(toml_text, overrides, source, false));
  config.validate();
  return config;
}

BlastConfig load_scene(const SceneRequest& request) {
  std::string text, source;
  if (!request.file.empty()) {
    text = common::read_text(request.file, "SCENE", common::text_size_limit);
    source = request.file;
  } else if (!request.text.empty()) {
    text = request.text;
    source = "scene";
  } else {
    text = default_scene_toml();
    source = "default scene";
  }
  BlastConfig config = config_from_table(scene_table(text, request.overrides, source, !request.md_snapshots));
  if (request.realizations) {
    require_integer_in_range("--realizations", *request.realizations, 1, 1000000000);
    config.realizations = *request.realizations;
  }
  if (request.seed) {
    require_integer_in_range("--seed", *request.seed, 0, std::numeric_limits<long long>::max());
    config.seed = static_cast<std::uint64_t>(*request.seed);
  }
  config.validate();
  return config;
}

std::string scene_toml(const BlastConfig& c) {
  std::ostringstream out;
  out << "name = " << quoted(c.name) << "\nd = " << c.d << "\nn = " << format_number(c.n)
      << "\na = " << format_number(c.a) << "\nE = " << format_number(c.E) << "\nA_d = " << format_number(c.A_d)
      << "\nt_min = " << format_number(c.t_min) << "\nt_max = " << format_number(c.t_max)
      << "\nrealizations = " << c.realizations << "\nseed = " << c.seed << "\nblock_size = " << c.block_size
      << "\nobservables = " << string_array(c.observables) << "\nbox_margin = " << format_number(c.box_margin)
      << "\ncell_width = " << format_number(c.cell_width) << "\nqueue = " << quoted(c.queue) << "\nsnapshot_times = [";
  for (std::size_t i = 0; i < c.snapshot_times.size(); ++i)
    out << (i ? ", " : "") << format_number(c.snapshot_times[i]);
  out << "]";
  // The snapshot keys beyond snapshot_times are written only when they differ from their defaults,
  // so that the text of a scene without them (compared by merges and resumes) stays what it was.
  const md::BlastConfig defaults;
  if (!c.snapshot_fractions.empty()) {
    out << "\nsnapshot_fractions = [";
    for (std::size_t i = 0; i < c.snapshot_fractions.size(); ++i)
      out << (i ? ", " : "") << format_number(c.snapshot_fractions[i]);
    out << "]";
  }
  if (c.region_growths != defaults.region_growths) out << "\nregion_growths = " << c.region_growths;
  if (c.snapshot_particles != defaults.snapshot_particles)
    out << "\nsnapshot_particles = " << quoted(c.snapshot_particles);
  if (c.snapshot_margin != defaults.snapshot_margin) out << "\nsnapshot_margin = " << format_number(c.snapshot_margin);
  if (c.snapshot_stride != defaults.snapshot_stride) out << "\nsnapshot_stride = " << c.snapshot_stride;
  if (c.snapshot_realizations != defaults.snapshot_realizations) {
    out << "\nsnapshot_realizations = [";
    for (std::size_t i = 0; i < c.snapshot_realizations.size(); ++i)
      out << (i ? ", " : "") << c.snapshot_realizations[i];
    out << "]";
  }
  out << "\nprofile_bins = " << c.profile_bins << "\np_imp_bins = " << c.p_imp_bins
      << "\noverlap_check = " << (c.overlap_check ? "true" : "false")
      << "\n\n[impurities]\ncount = " << c.impurities.count << "\nmass = " << format_number(c.impurities.mass)
      << "\nradius = " << format_number(c.impurities.radius) << "\n";
  // Written only when switched off, so the text of every ordinary scene (compared by merges and
  // resumes) is what it was before the key existed.
  if (!c.impurities.recollide) out << "recollide = false\n";
  // Likewise: a kick scene's text does not name its start.
  if (c.start.kind != md::StartKind::kick || c.start.r0 != 0.0)
    out << "\n[start]\nkind = " << quoted(md::start_kind_name(c.start.kind)) << "\nr0 = " << format_number(c.start.r0)
        << "\n";
  return out.str();
}

}  // namespace coldblast::run
