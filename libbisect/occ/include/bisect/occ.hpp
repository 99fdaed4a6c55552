// The B-rep route's reader (ARCHITECTURE.md §1): a .brep/.brp, .step/.stp or .iges/.igs file, or
// FreeCAD's Part.Shape handed over as a BREP string (`shape.exportBrepToString()`), read by
// OpenCASCADE and turned into a BrepInput. No OpenCASCADE type appears here, so the CLI and the
// Python module include this header without OpenCASCADE's.
//
// Which shapes: solids, CompSolids, compounds of solids (a face two solids share is one face, an
// interface), and closed shells or compounds of closed shells, each made a solid as Gmsh does.
// A shape without a closed volume is an InputError. Numbering is FreeCAD's (brep_input.hpp).
//
// The surfaces and curves of the result may be evaluated from several threads at once; reading
// and tessellate() are for one thread at a time per BrepInput.
#pragma once
#include <string>

#include "bisect/brep_input.hpp"

namespace bisect {

// Reads a B-rep file, by its extension (case-insensitive): .brep/.brp (OpenCASCADE's native
// format), .step/.stp, .iges/.igs. STEP and IGES lengths come in millimetres, as FreeCAD reads
// them. Throws InputError naming the file when it is missing, unreadable, of another extension,
// holds no shape, or holds no solid.
BrepInput load_brep_file(const std::string& path);

// Reads a shape written in OpenCASCADE's BREP text format (FreeCAD's exportBrepToString());
// `name` is the object's name for messages.
BrepInput load_brep_string(const std::string& brep, const std::string& name);

// True when `path` has one of the extensions load_brep_file reads.
bool is_brep_path(const std::string& path);

}  // namespace bisect
