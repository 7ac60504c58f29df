#pragma once
// Input validation at the boundaries: every failure throws std::invalid_argument naming the
// parameter, its value and the allowed range (STYLE.md, "Errors: loud at the boundary").
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace coldblast::common {

/// Kind of interval bound used in messages: "(" / "[" style.
enum class Bound { open, closed };

/// Throws std::invalid_argument("name = value is outside (lo, hi) context") unless value lies in the interval
/// (one space before a non-empty context, whatever spaces it starts with).
/// Use ±infinity for a missing bound. Also rejects non-finite values.
void require_in_range(const std::string& name, double value, double lo, double hi, Bound lo_bound = Bound::open,
                      Bound hi_bound = Bound::open, const std::string& context = "");

/// Integer version: value must lie in [lo, hi].
void require_integer_in_range(const std::string& name, long long value, long long lo, long long hi,
                              const std::string& context = "");

/// Shortest round-trip decimal form of a double (17 significant digits at most).
std::string format_number(double value);

/// `value` rounded to `digits` significant digits in format_number's form (3363.585661 → "3363.59"
/// for 6, 12345 → "12350" for 4), for reports and figure labels; the data files keep full
/// precision (format_number). Non-finite or zero: format_number.
std::string format_significant(double value, int digits);

/// "value ± error" with the error rounded to `error_digits` significant digits and the value to the
/// same decimal place (1.837558 ± 0.036612 → "1.838 ± 0.037"; 0.35193590684 ± 2.5e-14 →
/// "0.351935906848599 ± 2.5e-14"), the way a measurement is quoted. An error that is not finite and
/// positive leaves both at full precision (format_number).
std::string format_measurement(double value, double error, int error_digits = 2);

/// A front end's names for a library config's fields, {field, name} (e.g. {"phi", "--phi"} for a
/// flag, {"phi", "hydro.phi"} for a TOML key): the one place a command maps its flags or keys.
using FieldNames = std::vector<std::pair<std::string, std::string>>;

/// `message` with every field of `names` that stands as a word before " = " renamed: "phi = 0.8 is
/// outside ..." becomes "--phi = 0.8 is outside ...".
std::string rename_fields(const std::string& message, const FieldNames& names);

/// Returns f(); a std::invalid_argument thrown by f (a config's validate(), a parser) is rethrown
/// with rename_fields, so the library validates and the message names the caller's flag or key.
template <class F>
auto with_field_names(const FieldNames& names, F&& f) -> decltype(f()) {
  try {
    return f();
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(rename_fields(e.what(), names));
  }
}

}  // namespace coldblast::common
