#include "common/validate.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace coldblast::common {

std::string format_number(double value) {
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  if (std::isnan(value)) return "nan";
  // "%.*g" with the fewest digits >= 6 that read back to the same double. std::to_chars (Ryu)
  // finds the shortest round-trip digits directly; the snprintf/strtod loop it replaces cost
  // ~25000 instructions per number and half of a one-realization `md run` (snapshot tables).
  char buffer[64];
  const auto shortest = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::scientific);
  int digits = 0;
  for (const char* c = buffer; c != shortest.ptr && *c != 'e'; ++c) digits += *c >= '0' && *c <= '9';
  const auto end =
      std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::general, std::max(6, digits));
  return std::string(buffer, end.ptr);
}

std::string format_significant(double value, int digits) {
  if (!std::isfinite(value) || value == 0.0 || digits < 1) return format_number(value);
  // Rounded at the digit's power of ten, then the shortest form of that double: 12345 → "12350"
  // and 3363.5857 → "3363.59" (never "1.234e+04" as "%.4g" prints). A power 10^k with |k| <= 22 is
  // exact, so the rounding is the nearest double to the decimal.
  const int place = static_cast<int>(std::floor(std::log10(std::abs(value)))) - (std::min(digits, 17) - 1);
  const double rounded = place < 0 ? std::round(value * std::pow(10.0, -place)) / std::pow(10.0, -place)
                                   : std::round(value / std::pow(10.0, place)) * std::pow(10.0, place);
  return format_number(rounded);
}

namespace {
/// `x`, already rounded to a multiple of 10^place, with its digits down to that place: fixed
/// notation for moderate places ("0.037", "232.500", "3364"), else "%#.*g" ("2.5e-14").
std::string format_at_place(double x, int place) {
  char buffer[64];
  if (x == 0.0) x = 0.0;  // no "-0.00"
  if (place >= 0 && std::abs(x) < 1e15) {
    std::snprintf(buffer, sizeof buffer, "%.0f", x);
  } else if (place < 0 && place >= -9 && std::abs(x) < 1e9) {
    std::snprintf(buffer, sizeof buffer, "%.*f", -place, x);
  } else {
    const int magnitude = x == 0.0 ? place : static_cast<int>(std::floor(std::log10(std::abs(x))));
    const int significant = std::clamp(magnitude - place + 1, 1, 17);
    std::snprintf(buffer, sizeof buffer, "%#.*g", significant, x);
    std::string text = buffer;
    if (!text.empty() && text.back() == '.') text.pop_back();
    return text;
  }
  return buffer;
}
}  // namespace

std::string format_measurement(double value, double error, int error_digits) {
  if (!std::isfinite(value) || !std::isfinite(error) || !(error > 0.0) || error_digits < 1)
    return format_number(value) + " ± " + format_number(error);
  int place = static_cast<int>(std::floor(std::log10(error))) - (error_digits - 1);
  double unit = std::pow(10.0, place);
  double rounded_error = std::round(error / unit) * unit;
  if (rounded_error >= std::pow(10.0, place + error_digits) * (1.0 - 1e-12)) {  // 0.0996 → 0.10: one place up
    ++place;
    unit = std::pow(10.0, place);
    rounded_error = std::round(error / unit) * unit;
  }
  return format_at_place(std::round(value / unit) * unit, place) + " ± " + format_at_place(rounded_error, place);
}

namespace {
/// " context" after the range, one space whatever spaces the caller put first ("" for none).
std::string context_suffix(const std::string& context) {
  const std::size_t start = context.find_first_not_of(' ');
  return start == std::string::npos ? "" : " " + context.substr(start);
}
}  // namespace

void require_in_range(const std::string& name, double value, double lo, double hi, Bound lo_bound, Bound hi_bound,
                      const std::string& context) {
  const bool above = lo_bound == Bound::open ? value > lo : value >= lo;
  const bool below = hi_bound == Bound::open ? value < hi : value <= hi;
  if (std::isfinite(value) && above && below) return;
  const std::string range = std::string(lo_bound == Bound::open ? "(" : "[") + format_number(lo) + ", " +
                            format_number(hi) + (hi_bound == Bound::open ? ")" : "]");
  throw std::invalid_argument(name + " = " + format_number(value) + " is outside " + range + context_suffix(context));
}

void require_integer_in_range(const std::string& name, long long value, long long lo, long long hi,
                              const std::string& context) {
  if (value >= lo && value <= hi) return;
  const std::string hi_text = hi == std::numeric_limits<long long>::max() ? "inf" : std::to_string(hi);
  throw std::invalid_argument(name + " = " + std::to_string(value) + " is outside [" + std::to_string(lo) + ", " +
                              hi_text + "]" + context_suffix(context));
}

std::string rename_fields(const std::string& message, const FieldNames& names) {
  std::string out;
  std::size_t i = 0;
  while (i < message.size()) {
    const bool word_start = i == 0 || message[i - 1] == ' ' || message[i - 1] == '(' || message[i - 1] == ',';
    const FieldNames::value_type* match = nullptr;
    if (word_start)
      for (const auto& entry : names)
        if (message.compare(i, entry.first.size() + 3, entry.first + " = ") == 0) match = &entry;
    if (match) {
      out += match->second;
      i += match->first.size();
    } else {
      out += message[i++];
    }
  }
  return out;
}

}  // namespace coldblast::common
