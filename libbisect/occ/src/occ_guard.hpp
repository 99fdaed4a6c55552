// OpenCASCADE reports failures with Standard_Failure, which in 7.6 is no std::exception: left to
// escape, it would pass every handler of the pipeline and the Python module and end FreeCAD's
// session. Every OpenCASCADE call that can throw runs inside guard(), which turns it into our
// exception naming the object (face, edge, file) it was working on.
#pragma once
#include <Standard_Failure.hxx>
#include <Standard_Type.hxx>

#include <new>
#include <string>

#include "bisect/errors.hpp"

namespace bisect::occ {

// "Standard_ConstructionError: <message>" on one line.
inline std::string describe(const Standard_Failure& e) {
  std::string s = e.DynamicType()->Name();
  const char* m = e.GetMessageString();
  if (m && *m) s += std::string(": ") + m;
  for (char& c : s)
    if (c == '\n' || c == '\r') c = ' ';
  while (!s.empty() && s.back() == ' ') s.pop_back();
  return s;
}

// Runs f(); an OpenCASCADE failure or exhausted memory becomes E("<where>: <doing> (<what OCC
// said>)"). `where` is called only on failure, so building the name costs nothing on success.
// Our own exceptions pass through untouched.
template <class E = InputError, class Where, class F>
auto guard(Where&& where, const char* doing, F&& f) -> decltype(f()) {
  try {
    return f();
  } catch (const bisect::Error&) {
    throw;
  } catch (const Standard_Failure& e) {
    throw E(std::string(where()) + ": " + doing + " (" + describe(e) + ")");
  } catch (const std::bad_alloc&) {
    throw E(std::string(where()) + ": " + doing + " (out of memory)");
  } catch (const std::exception& e) {
    throw E(std::string(where()) + ": " + doing + " (" + e.what() + ")");
  }
}

}  // namespace bisect::occ
