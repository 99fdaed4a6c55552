// GenerateOptions from Python keyword arguments, in one place for every entry point of the
// module (ARCHITECTURE.md §6: one options struct bound once). Names and meanings follow the CLI's
// flags; a bad value raises ValueError (bisect::InputError) naming the argument.
#pragma once
#include <pybind11/pybind11.h>

#include "bisect/generate.hpp"

namespace bisect::python {

// The keyword arguments the generators take, with their defaults (GenerateOptions' own).
pybind11::dict default_options();

// Reads `kwargs` (any key of default_options(); an unknown key is an error) over the defaults.
// `progress` is not an option here: the caller wraps it.
GenerateOptions generate_options(const pybind11::dict& kwargs);

}  // namespace bisect::python
