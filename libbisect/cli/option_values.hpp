// The numbers the command line takes, read strictly: a value out of its range (overflowing, NaN,
// infinite, negative, zero where zero means nothing) is refused with a message naming the flag
// and the value as typed, never clamped or wrapped.
#pragma once
#include <cstdint>
#include <optional>
#include <string>

namespace bisect::cli {

// A whole number in [lo, hi]: decimal digits, or a whole number in exponent notation ("1e6",
// "2.5e4"), as counts are often written. On failure `error` gets "FLAG needs WHAT from LO to HI,
// not 'TEXT'" with the reason (too large, not whole, ...), and the result is empty.
std::optional<std::int64_t> parse_whole(const std::string& flag, const std::string& text, std::int64_t lo, std::int64_t hi,
                                        const std::string& what, std::string* error);

// A finite real number in [lo, hi] (lo excluded when `lo_open`); `zero_ok` also admits exactly 0
// (an "off" value below the range).
std::optional<double> parse_real(const std::string& flag, const std::string& text, double lo, bool lo_open, double hi,
                                 bool zero_ok, const std::string& what, std::string* error);

}  // namespace bisect::cli
