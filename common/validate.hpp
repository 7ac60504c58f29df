#pragma once
// Input validation at the boundaries: every failure throws std::invalid_argument naming the
// parameter, its value and the allowed range (STYLE.md, "Errors: loud at the boundary").
#include <string>

namespace coldblast::common {

/// Kind of interval bound used in messages: "(" / "[" style.
enum class Bound { open, closed };

/// Throws std::invalid_argument("name = value is outside (lo, hi)<context>") unless value lies in the interval.
/// Use ±infinity for a missing bound. Also rejects non-finite values.
void require_in_range(const std::string& name, double value, double lo, double hi, Bound lo_bound = Bound::open,
                      Bound hi_bound = Bound::open, const std::string& context = "");

/// Integer version: value must lie in [lo, hi].
void require_integer_in_range(const std::string& name, long long value, long long lo, long long hi,
                              const std::string& context = "");

/// Shortest round-trip decimal form of a double (17 significant digits at most).
std::string format_number(double value);

}  // namespace coldblast::common
