// JSON text for the figures the CLI and the Python module hand out (--stats, --json).
#pragma once
#include <string>

namespace bisect {

// s as a JSON string literal, quotes included: quotes, backslashes and control characters
// escaped (messages carry file paths and quoted names).
std::string json_string(const std::string& s);

}  // namespace bisect
