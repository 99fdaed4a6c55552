// Mesh readers and writers on bad input (io/mesh_io.cpp and the per-format files): the errors
// they must raise, naming the file and the place.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "bisect/errors.hpp"
#include "bisect/io.hpp"
#include "input_error.hpp"
#include "io/mesh_formats.hpp"
#include "mesh_io_grid.hpp"

namespace bisect {
namespace {

using test::grid_mesh;
using Reader = TetMesh (*)(std::istream&, const std::string&);

const std::string kData = std::string(BISECT_TEST_DATA) + "/meshes/";

// ---- bad input ----

using bisect::test::error_of;

std::string read_error(Reader r, const std::string& text, const std::string& name) {
  return error_of([&] {
    std::istringstream in(text);
    r(in, name);
  });
}

TEST(MeshIoErrors, UnknownExtension) {
  const TetMesh m = grid_mesh(1, 1);
  std::string e = error_of([&] { write_mesh(m, testing::TempDir() + "x.stl"); });
  EXPECT_NE(e.find(".vtu, .msh"), std::string::npos) << e;
  EXPECT_NE(e.find(".unv"), std::string::npos) << e;
  e = error_of([&] { read_mesh("mesh.unv"); });
  EXPECT_NE(e.find("supported: .vtu, .msh"), std::string::npos) << e;
  e = error_of([&] { read_mesh("noext"); });
  EXPECT_NE(e.find("(no extension)"), std::string::npos) << e;
  e = error_of([&] { read_mesh(testing::TempDir() + "does-not-exist.msh"); });
  EXPECT_NE(e.find("cannot open"), std::string::npos) << e;
}

TEST(MeshIoErrors, TruncatedMsh) {
  std::ifstream in(kData + "box2_o1.msh");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t cut = text.find("$Elements") + 200;  // inside the element blocks
  const long lines = long(std::count(text.begin(), text.begin() + cut, '\n')) + 1;
  const std::string e = read_error(meshio::read_msh, text.substr(0, cut), "cut.msh");
  EXPECT_EQ(e.rfind("cut.msh:", 0), 0u) << e;
  EXPECT_NE(e.find(":" + std::to_string(lines) + ":"), std::string::npos) << e;
  // Cut at the very end of the last element line: the missing $EndElements is reported.
  const std::string e2 = read_error(meshio::read_msh, text.substr(0, text.find("$EndElements")), "cut2.msh");
  EXPECT_NE(e2.find("end of file"), std::string::npos) << e2;
}

TEST(MeshIoErrors, UndefinedNode) {
  std::stringstream s;
  meshio::write_msh(grid_mesh(1, 1), s);
  std::string t = s.str();
  // Element 3 (a tetrahedron: our writer numbers them first) gets node 99.
  const std::size_t block = t.find("\n3 1 4 6\n", t.find("$Elements"));
  const std::size_t at = t.find("\n3 ", block + 1);
  t.replace(at + 3, t.find(' ', at + 3) - (at + 3), "99");
  std::string e = read_error(meshio::read_msh, t, "bad.msh");
  EXPECT_NE(e.find("element 3 references node 99"), std::string::npos) << e;

  const std::string inp = "*NODE\n1, 0, 0, 0\n2, 1, 0, 0\n3, 0, 1, 0\n4, 0, 0, 1\n*ELEMENT, TYPE=C3D4\n7, 1, 2, 3, 4\n8, 1, 2,\n 4, 5\n";
  e = read_error(meshio::read_inp, inp, "bad.inp");
  EXPECT_EQ(e, "bad.inp:8: element 8 references node 5, which is not defined");
}

TEST(MeshIoErrors, BinaryMshAndOtherVersions) {
  std::string e = read_error(meshio::read_msh, "$MeshFormat\n4.1 1 8\n\x01\x00\x00\x00\n$EndMeshFormat\n", "bin.msh");
  EXPECT_EQ(e, "bin.msh:2: binary .msh is not supported, re-export with -format msh41 ASCII (gmsh -bin 0)");
  e = read_error(meshio::read_msh, "$MeshFormat\n4 0 8\n$EndMeshFormat\n", "v40.msh");
  EXPECT_NE(e.find("4.1 or 2.2"), std::string::npos) << e;
  e = read_error(meshio::read_msh, "solid x\n", "stl.msh");
  EXPECT_NE(e.find("not a Gmsh .msh file"), std::string::npos) << e;
}

TEST(MeshIoErrors, MixedOrders) {
  std::stringstream s;
  meshio::write_vtu(grid_mesh(1, 1), s);
  std::string t = s.str();
  // Turn the first tetrahedron into a 10-node one by pointing its offsets and type at more nodes.
  const std::size_t types = t.find("10 ", t.find("Name=\"types\""));
  t.replace(types, 2, "24");
  std::string e = read_error(meshio::read_vtu, t, "mixed.vtu");
  EXPECT_NE(e.find("mixed.vtu:"), std::string::npos) << e;
  EXPECT_NE(e.find("cell 0 of type 24 has 4 points"), std::string::npos) << e;

  const std::string two =
      "<VTKFile type=\"UnstructuredGrid\"><UnstructuredGrid><Piece NumberOfPoints=\"10\" NumberOfCells=\"2\">\n"
      "<Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n"
      "0 0 0 1 0 0 0 1 0 0 0 1 .5 0 0 .5 .5 0 0 .5 0 0 0 .5 .5 0 .5 0 .5 .5</DataArray></Points>\n"
      "<Cells><DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">0 1 2 3\n0 1 2 3 4 5 6 7 8 9</DataArray>\n"
      "<DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">4 14</DataArray>\n"
      "<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">10 24</DataArray></Cells></Piece></UnstructuredGrid></VTKFile>\n";
  e = read_error(meshio::read_vtu, two, "two.vtu");
  EXPECT_EQ(e, "two.vtu:4: 4-node and 10-node tetrahedra in one mesh (cell 1)");

  const std::string inp =
      "*NODE\n1,0,0,0\n2,1,0,0\n3,0,1,0\n4,0,0,1\n5,1,1,1\n*ELEMENT,TYPE=C3D4\n1,1,2,3,4\n"
      "*ELEMENT,TYPE=C3D10T\n2,1,2,3,4,1,2,3,4,5,5\n";
  e = read_error(meshio::read_inp, inp, "mixed.inp");
  EXPECT_EQ(e, "mixed.inp:9: C3D4 and C3D10 elements in one mesh");
}

TEST(MeshIoErrors, TruncatedInp) {
  const std::string inp = "*NODE\n1,0,0,0\n2,1,0,0\n3,0,1,0\n4,0,0,1\n*ELEMENT, TYPE=C3D10, ELSET=A\n1, 1, 2, 3, 4, 1,\n";
  EXPECT_EQ(read_error(meshio::read_inp, inp, "cut.inp"), "cut.inp:7: element 1 has 5 nodes, expected 10 (truncated record?)");
}

TEST(MeshIoErrors, VtuAppendedAndTruncated) {
  std::stringstream s;
  meshio::write_vtu(grid_mesh(1, 1), s);
  const std::string t = s.str();
  std::string e = read_error(meshio::read_vtu, t.substr(0, t.size() / 2), "cut.vtu");
  EXPECT_NE(e.find("truncated"), std::string::npos) << e;
  std::string app = t;
  app.replace(app.find("format=\"ascii\""), 14, "format=\"appended\" offset=\"0\"");
  e = read_error(meshio::read_vtu, app, "app.vtu");
  EXPECT_NE(e.find("app.vtu:6: appended data is not supported"), std::string::npos) << e;
}

TEST(MeshIoErrors, UnwritableMesh) {
  TetMesh m = grid_mesh(1, 1);
  m.tets[5] = 1000;
  const std::string path = testing::TempDir() + "unwritable.msh";
  std::remove(path.c_str());
  const std::string e = error_of([&] { write_mesh(m, path); });
  EXPECT_NE(e.find("tetrahedron 2 refers to node index 1000"), std::string::npos) << e;
  EXPECT_FALSE(std::ifstream(path).good()) << "no file is left behind";
}

}  // namespace
}  // namespace bisect
