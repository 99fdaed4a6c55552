// bisect-mesh run as a user runs it: exit codes, the lines it prints, the one-line errors.
#include <gtest/gtest.h>

#include "cli_run.hpp"
#include "poly_shapes.hpp"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>

namespace fs = std::filesystem;

namespace {

using bisect::test::CliResult;
using bisect::test::count_lines;
using bisect::test::slurp;

fs::path scratch_dir() { return bisect::test::scratch_dir("test"); }

CliResult run(const std::string& args) { return bisect::test::run_cli(args, "test"); }

fs::path write_file(const std::string& name, const std::string& text) {
  const fs::path p = scratch_dir() / name;
  std::ofstream(p) << text;
  return p;
}

const std::string kExamples = BISECT_EXAMPLES_DIR;

}  // namespace

TEST(Cli, HelpAndVersion) {
  CliResult r = run("--help");
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("info INPUT"), std::string::npos);
  EXPECT_NE(r.out.find("quality MESH"), std::string::npos);
  r = run("--version");
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("bisect-mesh"), std::string::npos);
}

TEST(Cli, UsageErrorsExitTwoWithOneLine) {
  for (const char* args : {"", "frobnicate x.poly", "info", "info --bogus x.poly", "info a.poly b.poly"}) {
    const CliResult r = run(args);
    EXPECT_EQ(r.code, 2) << args;
    EXPECT_EQ(count_lines(r.err), 1) << args << ": " << r.err;
    EXPECT_TRUE(r.out.empty()) << args;
  }
}

TEST(Cli, InfoOnTheThesisCubeWithCavity) {
  const CliResult r = run("info '" + kExamples + "/cube-cavity-adjacent-cube.poly'");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("3 regions, 17 faces, 20 nodes"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("bounding box: (0, 0, 0) to (2, 1, 1)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("region 1: 6 faces, 8 nodes, 1 shell, volume 0.875"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("region 2: 6 faces, 8 nodes, 1 shell, volume 1"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("region 3: cavity, 6 faces, 8 nodes, 1 shell, inside region 1, volume 0.125"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("volume: 1.875"), std::string::npos) << r.out;
}

TEST(Cli, InfoJson) {
  const CliResult r = run("info --json '" + kExamples + "/cube-cavity-adjacent-cube.poly'");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out.front(), '{');
  EXPECT_NE(r.out.find("\"cavity\":true,\"inside\":1,\"volume\":0.125"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"required_elements\":26"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"volume\":1.875}"), std::string::npos) << r.out;
}

TEST(Cli, InfoOnPoly2) {
  const fs::path p = write_file("hole.poly2",
                                "50\n10 3\n4 4 -4\n0 0\n1 0\n1 1\n0 1\n2 0\n2 1\n"
                                "0.25 0.25\n0.75 0.25\n0.75 0.75\n0.25 0.75\n1 2 3 4\n2 5 6 3\n7 8 9 10\n");
  const CliResult r = run("info '" + p.string() + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("polygon 1: region, 4 nodes, area 1, net area 0.75"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("polygon 3: hole, 4 nodes, inside polygon 1, area 0.25"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("area: 1.75"), std::string::npos) << r.out;
}

TEST(Cli, InfoBadInputNamesTheFaceAndExitsTwo) {
  const fs::path p = write_file("bad.poly",
                                "1 3 1 10\n0 0 0\n1 0 0\n0 1 0\n3 1 2 9\n1 1\n");
  const CliResult r = run("info '" + p.string() + "'");
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("bad.poly"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("node 9"), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty());
}

TEST(Cli, InfoMissingFile) {
  const CliResult r = run("info /nonexistent/file.poly");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("/nonexistent/file.poly"), std::string::npos) << r.err;
}

TEST(Cli, QualityOfTheBundledGmshMesh) {
  const CliResult r = run("quality '" + kExamples + "/box-minus-cylinder.msh'");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("valid: yes"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("min dihedral angle"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("gamma histogram"), std::string::npos) << r.out;
  const CliResult j = run("quality --json '" + kExamples + "/box-minus-cylinder.msh'");
  ASSERT_EQ(j.code, 0) << j.err;
  EXPECT_NE(j.out.find("\"valid\":true"), std::string::npos);
  EXPECT_NE(j.out.find("\"pct_dihedral_below_10\""), std::string::npos);
}

TEST(Cli, QualityOfAnInvalidMeshNamesTheElement) {
  // Element 7 is inverted (its last two corners swapped); element 8 is positive.
  const fs::path p = write_file("inverted.inp",
                                "*NODE\n1, 0, 0, 0\n2, 1, 0, 0\n3, 0, 1, 0\n4, 0, 0, 1\n5, 1, 1, 1\n"
                                "*ELEMENT, TYPE=C3D4, ELSET=Solid\n7, 1, 2, 4, 3\n8, 2, 3, 4, 5\n");
  const CliResult r = run("quality '" + p.string() + "'");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.out.find("valid: no"), std::string::npos) << r.out;
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("7"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("invert"), std::string::npos) << r.err;
}

TEST(Cli, CellsOnlyWritesConvexCellsAndStats) {
  const fs::path cells = scratch_dir() / "cells.poly", stats = scratch_dir() / "stats.json";
  const CliResult r = run("'" + std::string(BISECT_TEST_DATA) + "/cube-cavity-adjacent-cube.poly' --cells-only -o '" +
                          cells.string() + "' --stats '" + stats.string() + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("convex cells"), std::string::npos) << r.out;
  // the cells read back as a valid .poly with the input's volume (1 - 1/8 + 1)
  const CliResult info = run("info '" + cells.string() + "' --json");
  ASSERT_EQ(info.code, 0) << info.err;
  EXPECT_NE(info.out.find("\"volume\":1.875}"), std::string::npos) << info.out;
  const std::string s = slurp(stats);
  for (const char* key : {"\"convex_cells\"", "\"bisections\"", "\"rejected_planes\"", "\"init_geom\"", "\"bisect\""})
    EXPECT_NE(s.find(key), std::string::npos) << key << " in " << s;
}

TEST(Cli, MainJobErrorsExitTwo) {
  const std::string in = "'" + std::string(BISECT_TEST_DATA) + "/reentry-box.poly'";
  CliResult r = run(in + " --cells-only");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("no output file"), std::string::npos) << r.err;
  r = run(in + " -o '" + (scratch_dir() / "out.poly").string() + "'");  // tetrahedra are not .poly
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find(".vtu, .msh, .inp or .unv"), std::string::npos) << r.err;
  // any other extension no writer takes is refused before the job is even sized (it was refused
  // only once the mesh was made, seconds or minutes later): the output's name, not the size
  const fs::path vtk = scratch_dir() / "out.vtk";
  fs::remove(vtk);
  r = run(in + " -n 1e9 -o '" + vtk.string() + "'");
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("out.vtk: cannot write a tetrahedral mesh as '.vtk'"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("--max-memory"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(vtk));
  r = run(in + " -o '" + (scratch_dir() / "out.vtu").string() + "' -s -1");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("-s needs a positive size"), std::string::npos) << r.err;
  r = run(in + " -o '" + (scratch_dir() / "out.vtu").string() + "' --insertion bowyer");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("minmax or delaunay"), std::string::npos) << r.err;
  r = run(in + " --cells-only -o");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("-o needs a file name"), std::string::npos) << r.err;
  // an open surface: the reader names the open edge
  const fs::path open = write_file("open.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n3 0 1 3\n");
  r = run("'" + open.string() + "' --cells-only -o '" + (scratch_dir() / "c.poly").string() + "'");
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
}

// The main job: tetrahedra of the thesis's two regions, written, read back valid by `quality`,
// with the statistics of ARCHITECTURE.md §3; both insertion methods and -s.
TEST(Cli, MeshesTheThesisCubesIntoTetrahedra) {
  const fs::path out = scratch_dir() / "cubes.vtu", stats = scratch_dir() / "cubes.json", inp = scratch_dir() / "cubes.inp";
  const std::string in = "'" + std::string(BISECT_TEST_DATA) + "/cube-cavity-adjacent-cube.poly'";
  CliResult r = run(in + " -n 3000 -o '" + out.string() + "' --stats '" + stats.string() + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("tetrahedra"), std::string::npos) << r.out;
  const std::string s = slurp(stats);
  for (const char* key : {"\"nodes\"", "\"tets\"", "\"regions\": 2", "\"convex_cells\"", "\"init_geom\"", "\"bisect\"", "\"gen_nodes\"",
                          "\"gen_tets\"", "\"optimize\"", "\"optimize_blocks\": 0", "\"face_corner_retry\": false", "\"total\"", "\"dihedral_min\"", "\"alpha_mean\"", "\"pct_dihedral_below_10\""})
    EXPECT_NE(s.find(key), std::string::npos) << key << " in " << s;
  // where the optimisation's time went: seven parts, none negative, together within its time
  const auto number_after = [&](const std::string& from, const char* key) {
    const std::size_t at = s.find(std::string("\"") + key + "\": ", s.find(from));
    return at == std::string::npos ? -1.0 : std::atof(s.c_str() + at + std::string(key).size() + 4);
  };
  const double optimize = number_after("\"times\"", "optimize");
  double parts = 0;
  for (const char* part : {"build", "blocks", "flips", "smooth", "refill", "slivers", "mean"}) {
    const double x = number_after("\"optimize_parts\"", part);
    EXPECT_GE(x, 0) << part << " in " << s;
    parts += x;
  }
  EXPECT_GT(parts, 0) << s;
  EXPECT_LE(parts, optimize * 1.001 + 1e-4) << s;
  CliResult q = run("quality '" + out.string() + "'");
  EXPECT_EQ(q.code, 0) << q.out << q.err;
  EXPECT_NE(q.out.find("valid: yes"), std::string::npos) << q.out;
  r = run(in + " -s 0.2 --insertion minmax --optimize 2 --smooth 0 -o '" + inp.string() + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  q = run("quality '" + inp.string() + "'");
  EXPECT_EQ(q.code, 0) << q.out << q.err;
  // 10-node tetrahedra on one thread, written for CalculiX, read back valid
  r = run(in + " -n 2000 --order 2 --threads 1 -o '" + inp.string() + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(slurp(inp).find("C3D10"), std::string::npos);
  q = run("quality '" + inp.string() + "'");
  EXPECT_EQ(q.code, 0) << q.out << q.err;
  EXPECT_NE(q.out.find("valid: yes"), std::string::npos) << q.out;
  for (const char* bad : {"--order 3", "--threads -1", "--threads many", "--grading -1"}) {
    r = run(in + " -n 2000 " + bad + " -o '" + inp.string() + "'");
    EXPECT_EQ(r.code, 2) << bad;
    EXPECT_EQ(count_lines(r.err), 1) << bad << ": " << r.err;
  }
}

// --no-face-moves: the mean shape's passes leave the nodes inside the input faces where the grids
// put them. On the thesis's cubes at R = 1000 the run with face moves makes more changes and a
// different mesh; both are valid.
TEST(Cli, NoFaceMovesKeepsTheFacesNodesWhereTheGridsPutThem) {
  const std::string in = "'" + std::string(BISECT_TEST_DATA) + "/cube-cavity-adjacent-cube.poly'";
  std::string mesh[2], stats[2];
  for (int moves : {0, 1}) {
    const fs::path out = scratch_dir() / ("moves" + std::to_string(moves) + ".vtu");
    const fs::path json = scratch_dir() / ("moves" + std::to_string(moves) + ".json");
    const CliResult r = run(in + " -n 1000 --threads 1" + (moves ? "" : " --no-face-moves") + " -o '" + out.string() + "' --stats '" + json.string() + "'");
    ASSERT_EQ(r.code, 0) << r.err;
    const CliResult q = run("quality '" + out.string() + "'");
    EXPECT_NE(q.out.find("valid: yes"), std::string::npos) << q.out;
    mesh[moves] = slurp(out), stats[moves] = slurp(json);
  }
  const auto changes = [](const std::string& s) {
    const std::size_t at = s.find("\"mean_changes\": ");
    return at == std::string::npos ? -1L : std::atol(s.c_str() + at + 16);
  };
  EXPECT_GT(changes(stats[1]), changes(stats[0])) << stats[0] << "\n" << stats[1];
  EXPECT_NE(mesh[0], mesh[1]);
}

// The count floor for quality's sake and --no-quality-floor: the plate with a round end at R = 300
// gets more tetrahedra, and --stats says why; with the flag it keeps the first mesh.
TEST(Cli, NoQualityFloorKeepsTheFirstMesh) {
  const fs::path in = write_file("round-ended-plate.poly", bisect::test::round_ended_plate());
  std::string stats[2];
  for (int floor : {0, 1}) {
    const fs::path out = scratch_dir() / ("floor" + std::to_string(floor) + ".vtu");
    const fs::path json = scratch_dir() / ("floor" + std::to_string(floor) + ".json");
    const CliResult r = run("'" + in.string() + "' -n 300" + (floor ? "" : " --no-quality-floor") + " -o '" + out.string() + "' --stats '" + json.string() + "'");
    ASSERT_EQ(r.code, 0) << r.err;
    stats[floor] = slurp(json);
  }
  const auto tets = [](const std::string& s) {
    const std::size_t at = s.find("\"tets\": ");
    return at == std::string::npos ? -1L : std::atol(s.c_str() + at + 8);
  };
  EXPECT_GT(tets(stats[1]), tets(stats[0]));
  EXPECT_NE(stats[1].find("\"count_floor_reason\": \"quality: the mesh for R = 300"), std::string::npos) << stats[1];
  EXPECT_EQ(stats[0].find("quality: the mesh"), std::string::npos) << stats[0];
  EXPECT_NE(stats[0].find("\"quality_meshes\": 0"), std::string::npos) << stats[0];
}

TEST(Cli, CellsOnlyRejectsACavityCrossingItsOuterBoundary) {
  // a unit cube with a cavity box that pokes out through the top face
  const fs::path in = write_file("crossing-cavity.poly", R"(12 16 2 0
0 0 0
1 0 0
1 1 0
0 1 0
0 0 1
1 0 1
1 1 1
0 1 1
0.25 0.25 0.5
0.75 0.25 0.5
0.75 0.75 0.5
0.25 0.75 0.5
0.25 0.25 1.5
0.75 0.25 1.5
0.75 0.75 1.5
0.25 0.75 1.5
4 1 2 3 4
4 5 6 7 8
4 1 2 6 5
4 2 3 7 6
4 3 4 8 7
4 4 1 5 8
4 9 10 11 12
4 13 14 15 16
4 9 10 14 13
4 10 11 15 14
4 11 12 16 15
4 12 9 13 16
6 1 2 3 4 5 6
-6 7 8 9 10 11 12
)");
  const CliResult r = run("'" + in.string() + "' --cells-only -o '" + (scratch_dir() / "c.poly").string() + "'");
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("faces 2 and "), std::string::npos) << r.err;  // the cube's top face
  EXPECT_NE(r.err.find("intersect at"), std::string::npos) << r.err;
}

TEST(Cli, MeshesA2DInputIntoVtu) {
  const fs::path out = scratch_dir() / "square.vtu", stats = scratch_dir() / "square.json";
  const std::string in = "'" + std::string(BISECT_TEST_DATA) + "/square-subdomain-adjacent-square.poly2'";
  CliResult r = run(in + " -o '" + out.string() + "' -n 800 --quads --stats '" + stats.string() + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("quadrilaterals"), std::string::npos) << r.out;
  EXPECT_NE(slurp(out).find("<UnstructuredGrid>"), std::string::npos);
  const std::string s = slurp(stats);
  for (const char* key : {"\"triangles\"", "\"quads\"", "\"min_angle\"", "\"times\""})
    EXPECT_NE(s.find(key), std::string::npos) << key << " in " << s;
  r = run(in + " -o '" + out.string() + "' -n 0");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("-n needs a positive whole number"), std::string::npos) << r.err;
  r = run(in + " -o '" + (scratch_dir() / "x.msh").string() + "'");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("2D meshes are written as .vtu"), std::string::npos) << r.err;
}

// A B-rep file through the main job: meshed on its true surfaces, per B-rep face in the .inp
// (FreeCAD's Face<k> numbering) an NSET, an ELSET and a SURFACE, and the help names the B-rep
// inputs.
TEST(Cli, MeshesABrepFileWithItsFaceSets) {
  const fs::path lug = fs::path(BISECT_SHARED_DIR) / "models" / "lug.brep";
  if (!fs::exists(lug)) GTEST_SKIP() << lug << " is missing";
  const fs::path out = scratch_dir() / "lug.inp";
  const CliResult r = run("'" + lug.string() + "' -n 3000 -o '" + out.string() + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string inp = slurp(out);
  int sets = 0;
  for (std::size_t at = inp.find("*NSET, NSET=Face"); at != std::string::npos; at = inp.find("*NSET, NSET=Face", at + 1)) ++sets;
  EXPECT_GE(sets, 6) << "one NSET per B-rep face";
  EXPECT_NE(inp.find("*NSET, NSET=Face1\n"), std::string::npos);
  int elsets = 0, surfaces = 0;
  for (std::size_t at = inp.find("*ELSET, ELSET=Face"); at != std::string::npos; at = inp.find("*ELSET, ELSET=Face", at + 1)) ++elsets;
  for (std::size_t at = inp.find("*SURFACE, NAME=Face"); at != std::string::npos; at = inp.find("*SURFACE, NAME=Face", at + 1)) ++surfaces;
  EXPECT_EQ(elsets, sets) << "one ELSET Face<k>_Elements per B-rep face";
  EXPECT_EQ(surfaces, sets) << "one SURFACE Face<k>_Surface per B-rep face";
  EXPECT_NE(inp.find("*SURFACE, NAME=Face1_Surface, TYPE=ELEMENT\n"), std::string::npos);
  EXPECT_NE(inp.find("C3D4"), std::string::npos);
  EXPECT_NE(run("--help").out.find(".step/.stp"), std::string::npos);
}
