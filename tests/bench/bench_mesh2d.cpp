// The planar mesher against Gmsh's 2D mesher and Triangle, in the same run, on a square with
// holes at about 1e3 .. 1e6 triangles: time, triangle count and smallest angle of each.
//
//   build/bench/bench_mesh2d [MAX_TRIANGLES]   (default 1000000)
//
// Gmsh is run as the `gmsh` program (`gmsh -2`), so its time includes starting the process and
// writing the mesh; Triangle (Debian's non-free triangle-bin) when tests/bench/fetch-triangle.sh
// has put it beside this program or it is on the PATH; likewise timed as a process.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "bisect/io.hpp"
#include "mesh2d/planar_mesher.hpp"

using namespace bisect;
using Clock = std::chrono::steady_clock;

namespace {

// A 4 x 4 square with four square holes of side 0.8.
const double kHoles[4][2] = {{0.6, 0.6}, {2.6, 0.6}, {0.6, 2.6}, {2.6, 2.6}};
const double kArea = 16 - 4 * 0.64;

Poly2Input square_with_holes() {
  std::ostringstream s;
  s << "1000\n20 5\n4 -4 -4 -4 -4\n0 0\n4 0\n4 4\n0 4\n";
  for (const auto& h : kHoles)
    s << h[0] << ' ' << h[1] << '\n' << h[0] + 0.8 << ' ' << h[1] << '\n' << h[0] + 0.8 << ' ' << h[1] + 0.8 << '\n' << h[0] << ' ' << h[1] + 0.8 << '\n';
  s << "1 2 3 4\n5 6 7 8\n9 10 11 12\n13 14 15 16\n17 18 19 20\n";
  std::istringstream in(s.str());
  return read_poly2(in, "square-with-holes.poly2");
}

double min_angle(const std::vector<Vec2>& p, const std::vector<std::array<int, 3>>& tris) {
  double worst = 180;
  for (const auto& t : tris)
    for (int k = 0; k < 3; ++k) {
      const Vec2 a = p[t[(k + 1) % 3]] - p[t[k]], b = p[t[(k + 2) % 3]] - p[t[k]];
      worst = std::min(worst, std::atan2(std::abs(a.x() * b.y() - a.y() * b.x()), a.dot(b)) * 180 / M_PI);
    }
  return worst;
}

struct Result {
  double seconds = 0, min_angle = 0;
  long triangles = 0;
  bool ran = false;
};

// Gmsh at the element size that gives about `want` triangles (one correction from a first run).
Result run_gmsh(long want) {
  Result r;
  double size = std::sqrt(4 * kArea / std::sqrt(3.0) / static_cast<double>(want));
  for (int round = 0; round < 2; ++round) {
    std::ofstream geo("/tmp/bench_mesh2d.geo");
    geo << "lc = " << size << ";\nPoint(1) = {0,0,0,lc}; Point(2) = {4,0,0,lc}; Point(3) = {4,4,0,lc}; Point(4) = {0,4,0,lc};\n"
        << "Line(1) = {1,2}; Line(2) = {2,3}; Line(3) = {3,4}; Line(4) = {4,1}; Curve Loop(1) = {1,2,3,4};\n";
    int id = 5;
    std::string loops = "1";
    for (int h = 0; h < 4; ++h) {
      const double x = kHoles[h][0], y = kHoles[h][1];
      geo << "Point(" << id << ") = {" << x << "," << y << ",0,lc}; Point(" << id + 1 << ") = {" << x + 0.8 << "," << y << ",0,lc}; "
          << "Point(" << id + 2 << ") = {" << x + 0.8 << "," << y + 0.8 << ",0,lc}; Point(" << id + 3 << ") = {" << x << "," << y + 0.8 << ",0,lc};\n"
          << "Line(" << id << ") = {" << id << "," << id + 1 << "}; Line(" << id + 1 << ") = {" << id + 1 << "," << id + 2 << "}; "
          << "Line(" << id + 2 << ") = {" << id + 2 << "," << id + 3 << "}; Line(" << id + 3 << ") = {" << id + 3 << "," << id << "};\n"
          << "Curve Loop(" << h + 2 << ") = {" << id << "," << id + 1 << "," << id + 2 << "," << id + 3 << "};\n";
      loops += "," + std::to_string(h + 2);
      id += 4;
    }
    geo << "Plane Surface(1) = {" << loops << "};\n";
    geo.close();
    const auto t0 = Clock::now();
    if (std::system("gmsh -2 -format msh2 -v 0 -o /tmp/bench_mesh2d.msh /tmp/bench_mesh2d.geo > /dev/null 2>&1") != 0) return r;
    r.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    // read the msh2 file: nodes and the 3-node triangles (type 2)
    std::ifstream in("/tmp/bench_mesh2d.msh");
    std::string line;
    std::vector<Vec2> p;
    std::vector<std::array<int, 3>> tris;
    while (std::getline(in, line)) {
      if (line == "$Nodes") {
        long n;
        in >> n;
        p.resize(n + 1);
        for (long i = 0; i < n; ++i) {
          long id2;
          double x, y, z;
          in >> id2 >> x >> y >> z;
          if (id2 >= static_cast<long>(p.size())) p.resize(id2 + 1);
          p[id2] = Vec2(x, y);
        }
      } else if (line == "$Elements") {
        long n;
        in >> n;
        std::getline(in, line);
        for (long i = 0; i < n; ++i) {
          std::getline(in, line);
          std::istringstream e(line);
          long id2, type, tags;
          e >> id2 >> type >> tags;
          for (long t = 0; t < tags; ++t) e >> id2;
          if (type != 2) continue;
          std::array<int, 3> t3;
          e >> t3[0] >> t3[1] >> t3[2];
          tris.push_back(t3);
        }
      }
    }
    r.triangles = static_cast<long>(tris.size());
    r.min_angle = min_angle(p, tris);
    r.ran = true;
    if (round == 0) size *= std::sqrt(static_cast<double>(r.triangles) / static_cast<double>(want));
  }
  return r;
}

// Triangle: the copy fetched by tests/bench/fetch-triangle.sh next to this program, else
// `triangle` on the PATH; empty when there is neither.
std::string triangle_program() {
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec && std::filesystem::exists(exe.parent_path() / "tools" / "triangle")) return (exe.parent_path() / "tools" / "triangle").string();
  if (std::system("command -v triangle > /dev/null 2>&1") == 0) return "triangle";
  return "";
}

// Triangle with a quality bound of 20 degrees and an area bound giving about `want` triangles
// (one correction from a first run, as for Gmsh).
Result run_triangle(long want) {
  Result r;
  const std::string program = triangle_program();
  if (program.empty()) return r;
  std::ofstream poly("/tmp/bench_mesh2d.poly");
  poly << "20 2 0 0\n1 0 0\n2 4 0\n3 4 4\n4 0 4\n";
  int id = 5;
  for (const auto& h : kHoles) {
    poly << id << ' ' << h[0] << ' ' << h[1] << '\n' << id + 1 << ' ' << h[0] + 0.8 << ' ' << h[1] << '\n';
    poly << id + 2 << ' ' << h[0] + 0.8 << ' ' << h[1] + 0.8 << '\n' << id + 3 << ' ' << h[0] << ' ' << h[1] + 0.8 << '\n';
    id += 4;
  }
  poly << "20 0\n";
  for (int loop = 0, s = 1; loop < 5; ++loop)
    for (int k = 0; k < 4; ++k, ++s) poly << s << ' ' << loop * 4 + k + 1 << ' ' << loop * 4 + (k + 1) % 4 + 1 << '\n';
  poly << "4\n";
  for (int h = 0; h < 4; ++h) poly << h + 1 << ' ' << kHoles[h][0] + 0.4 << ' ' << kHoles[h][1] + 0.4 << '\n';
  poly.close();
  double area = 2 * kArea / static_cast<double>(want);
  for (int round = 0; round < 2; ++round) {
    const std::string cmd = program + " -Qpq20a" + std::to_string(area) + " /tmp/bench_mesh2d.poly > /dev/null 2>&1";
    const auto t0 = Clock::now();
    if (std::system(cmd.c_str()) != 0) return r;
    r.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    std::ifstream node("/tmp/bench_mesh2d.1.node"), ele("/tmp/bench_mesh2d.1.ele");
    long n, dim, attr, marks;
    node >> n >> dim >> attr >> marks;
    std::vector<Vec2> p(n + 1);
    for (long i = 0; i < n; ++i) {
      long id2;
      double x, y, skip;
      node >> id2 >> x >> y;
      for (long k = 0; k < attr + marks; ++k) node >> skip;
      p[id2] = Vec2(x, y);
    }
    long ne, per, eattr;
    ele >> ne >> per >> eattr;
    std::vector<std::array<int, 3>> tris(ne);
    for (long i = 0; i < ne; ++i) {
      long id2;
      ele >> id2 >> tris[i][0] >> tris[i][1] >> tris[i][2];
    }
    r.triangles = ne;
    r.min_angle = min_angle(p, tris);
    r.ran = true;
    area *= static_cast<double>(ne) / static_cast<double>(want);
  }
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  const long max = argc > 1 ? std::atol(argv[1]) : 1000000;
  const Poly2Input in = square_with_holes();
  std::printf("square 4 x 4 with four 0.8 x 0.8 holes; min angle in degrees; Gmsh's time includes its process\n\n");
  std::printf("| request | BisectMesh tris | s | min angle | Gmsh tris | s | min angle | Triangle tris | s | min angle | "
              "time / Gmsh | time / Triangle |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (long want = 1000; want <= max; want *= 10) {
    mesh2d::PlanarOptions opt;
    opt.elements = want;
    mesh2d::PlanarStats st;
    const auto t0 = Clock::now();
    mesh2d::mesh_planar(in, opt, &st);
    const double ours = std::chrono::duration<double>(Clock::now() - t0).count();
    const Result g = run_gmsh(want), t = run_triangle(want);
    auto cell = [](const Result& r, double base) {
      char buf[96];
      if (!r.ran) return std::string("not run | - | -");
      std::snprintf(buf, sizeof buf, "%ld | %.3f | %.1f", r.triangles, r.seconds, r.min_angle);
      (void)base;
      return std::string(buf);
    };
    std::printf("| %ld | %lld | %.3f | %.1f | %s | %s | %s | %s |\n", want, static_cast<long long>(st.triangles), ours, st.min_angle_deg,
                cell(g, ours).c_str(), t.ran ? cell(t, ours).c_str() : "not installed | - | -",
                g.ran ? std::to_string(ours / g.seconds).substr(0, 5).c_str() : "-",
                t.ran ? std::to_string(ours / t.seconds).substr(0, 5).c_str() : "-");
    std::fflush(stdout);
  }
  return 0;
}
