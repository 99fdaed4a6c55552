// Errors that cross the library boundary. Every failure is an exception with a message that
// names what and where (face, node, line, element); nothing aborts, because inside FreeCAD a
// crash loses the user's unsaved work. The CLI maps InputError to exit 2 and MeshingError to 3.
#pragma once
#include <stdexcept>
#include <string>

namespace bisect {

class Error : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

// Bad input or options: a file that cannot be read, a malformed record, an invalid geometry.
class InputError : public Error {
public:
  using Error::Error;
};

// The mesher could not finish (what it could not resolve, and where).
class MeshingError : public Error {
public:
  using Error::Error;
};

// Long work was cancelled through the progress callback.
class Cancelled : public Error {
public:
  Cancelled() : Error("cancelled") {}
};

}  // namespace bisect
