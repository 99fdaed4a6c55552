// Readers and writers. Every reader validates what it reads and throws InputError with one line
// that names the file, the line (or record) and the offending node, face or element.
#pragma once
#include <iosfwd>
#include <string>

#include "bisect/poly_input.hpp"
#include "bisect/tet_mesh.hpp"

namespace bisect {

// Polyhedral inputs. read_polyhedral dispatches on the extension (.poly, .stl, .off).
PolyInput read_polyhedral(const std::string& path);
PolyInput read_poly(const std::string& path);
PolyInput read_poly(std::istream& in, const std::string& name);
PolyInput read_stl(const std::string& path);   // ASCII or binary, told apart by content
PolyInput read_stl(std::istream& in, const std::string& name);
PolyInput read_off(const std::string& path);
PolyInput read_off(std::istream& in, const std::string& name);
Poly2Input read_poly2(const std::string& path);
Poly2Input read_poly2(std::istream& in, const std::string& name);

// Tetrahedral meshes, by extension: .vtu (VTK XML), .msh (Gmsh 4.1 and 2.2 ASCII), .inp
// (Abaqus/CalculiX C3D4, C3D10). Only tetrahedra (and boundary triangles where the format tags
// them) are kept; other element types are skipped. Node order is converted to tet_mesh.hpp's.
TetMesh read_mesh(const std::string& path);

// By extension: .vtu, .msh (Gmsh 4.1 ASCII), .inp (C3D4/C3D10 with an element set per region
// and a node set per boundary tag), .unv (I-DEAS universal, datasets 2411/2412, as FreeCAD's
// Fem.read expects).
void write_mesh(const TetMesh& mesh, const std::string& path);
// The InputError write_mesh would throw for path's extension, before any meshing: a job whose
// output cannot be written is refused before it runs, not after.
void check_mesh_format(const std::string& path);

}  // namespace bisect
