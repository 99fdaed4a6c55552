// What every fuzz target shares: the input as a stream, and the line between a refusal and a
// crash. The library promises (bisect/errors.hpp) that every failure is a bisect::Error naming
// what and where; any other exception would reach FreeCAD's interpreter or the CLI's "internal
// error" path, so it is reported as a crash (abort, which libFuzzer records with the input).
// Signals, sanitizer reports and timeouts are libFuzzer's own findings.
#pragma once
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <sstream>
#include <string>
#include <typeinfo>

#include "bisect/errors.hpp"

namespace bisect::fuzz {

inline std::string as_string(const std::uint8_t* data, std::size_t size) {
  return std::string(reinterpret_cast<const char*>(data), size);
}

// Runs f(); bisect::Error (InputError, MeshingError, Cancelled) is the library refusing as
// documented, anything else aborts with its type and message.
template <class F>
int guarded(F&& f) {
  try {
    f();
  } catch (const bisect::Error&) {
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bisect fuzz: unexpected exception %s: %s\n", typeid(e).name(), e.what());
    std::abort();
  } catch (...) {
    std::fprintf(stderr, "bisect fuzz: unexpected non-std exception\n");
    std::abort();
  }
  return 0;
}

}  // namespace bisect::fuzz
