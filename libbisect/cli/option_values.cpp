#include "option_values.hpp"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace bisect::cli {
namespace {

std::string shown(const std::string& flag, const std::string& what, const std::string& text, const std::string& why) {
  return flag + " needs " + what + ", not '" + text + "'" + (why.empty() ? "" : " (" + why + ")");
}

// strtod over the whole text, or nothing (empty, trailing characters, leading spaces)
std::optional<double> whole_text_double(const std::string& text, bool* range_error) {
  *range_error = false;
  if (text.empty() || std::isspace(static_cast<unsigned char>(text[0]))) return std::nullopt;
  char* end = nullptr;
  errno = 0;
  const double x = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || *end != '\0') return std::nullopt;
  *range_error = errno == ERANGE && std::isinf(x);  // underflow to a tiny value is checked by range
  return x;
}

}  // namespace

std::optional<std::int64_t> parse_whole(const std::string& flag, const std::string& text, std::int64_t lo, std::int64_t hi,
                                        const std::string& what, std::string* error) {
  const std::string range = what + " from " + std::to_string(lo) + " to " + std::to_string(hi);
  bool digits = !text.empty();
  for (std::size_t i = 0; i < text.size(); ++i)
    digits = digits && (std::isdigit(static_cast<unsigned char>(text[i])) || (i == 0 && (text[i] == '-' || text[i] == '+')));
  if (digits) {
    char* end = nullptr;
    errno = 0;
    const long long n = std::strtoll(text.c_str(), &end, 10);
    if (errno == ERANGE || n > hi) return *error = shown(flag, range, text, "too large"), std::nullopt;
    if (n < lo) return *error = shown(flag, range, text, n < 0 ? "negative" : "too small"), std::nullopt;
    return n;
  }
  bool overflow = false;
  const std::optional<double> x = whole_text_double(text, &overflow);
  if (!x) return *error = shown(flag, range, text, "not a number"), std::nullopt;
  if (std::isnan(*x)) return *error = shown(flag, range, text, "not a number"), std::nullopt;
  if (overflow || *x > static_cast<double>(hi)) return *error = shown(flag, range, text, "too large"), std::nullopt;
  if (*x < static_cast<double>(lo)) return *error = shown(flag, range, text, *x < 0 ? "negative" : "too small"), std::nullopt;
  if (*x != std::floor(*x)) return *error = shown(flag, range, text, "not a whole number"), std::nullopt;
  return static_cast<std::int64_t>(*x);
}

std::optional<double> parse_real(const std::string& flag, const std::string& text, double lo, bool lo_open, double hi,
                                 bool zero_ok, const std::string& what, std::string* error) {
  bool overflow = false;
  const std::optional<double> x = whole_text_double(text, &overflow);
  if (!x || std::isnan(*x)) return *error = shown(flag, what, text, "not a number"), std::nullopt;
  if (overflow || std::isinf(*x)) return *error = shown(flag, what, text, "not finite"), std::nullopt;
  if (zero_ok && *x == 0) return 0.0;
  if (*x < 0 && lo >= 0) return *error = shown(flag, what, text, "negative"), std::nullopt;
  if (*x > hi) return *error = shown(flag, what, text, "too large"), std::nullopt;
  if (*x < lo || (lo_open && *x == lo)) return *error = shown(flag, what, text, *x == 0 ? "zero" : "too small"), std::nullopt;
  return *x;
}

}  // namespace bisect::cli
