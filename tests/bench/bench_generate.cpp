// The 3D generator measured (thesis ch. 8), with Gmsh and TetGen in the same run:
//
//   build/bench/bench_generate [MAX_R [OUT_DIR]]   (default 100000; 1000000 adds lug.stl at 10^6)
//
// 1. The CPU breakdown of thesis Tables 8.2.1-8.2.3 (box with a cavity, the two boxes of example
//    2, the lug) at R = 10^3 .. MAX_R: seconds per stage from --stats.
// 2. The alpha distribution of Table 8.3.1 on the slender appendage at about 3,600 tetrahedra.
// 3. Min-max against Delaunay on random points in a cube (Tables 8.3.2-8.3.3): our min-max
//    insertion, our Delaunay insertion, and TetGen's Delaunay tetrahedralisation of the points.
// 4. A scaling run on lug.stl from 10^3 to MAX_R tetrahedra, the fitted exponent, a PNG plot
//    (through plot_generate.py) next to the CSV in OUT_DIR (default: the working directory).
// 5. The STL models at R = 10^5 (and lug.stl at 10^6 when MAX_R allows) beside `gmsh -3 -algo
//    del3d` (its surfaces reclassified and remeshed from the STL; its 3D stage timed from its
//    log) and TetGen (`tetgen -pq1.414a`, on the same facets): tetrahedra, seconds, tetrahedra
//    per second, peak memory, mean alpha and the share of tetrahedra under 10 degrees. Every
//    tool runs as a child process (bisect-mesh too), timed, its peak memory polled from /proc;
//    each peer's size is corrected once towards our count. Ours runs twice: on every core (its
//    default) and on one thread, which makes the same mesh.
// 6. The strongest peer: Gmsh HXT (`-3 -algo hxt -nt 2`) from the B-rep models, end to end (its
//    surface mesh included), at our count on lug, flange, plate-hole and part.step at 10^5 (and
//    lug, flange, part at 10^6, lug at 5*10^6, as MAX_R allows): whole-process seconds at 2 and
//    1 threads, peak memory, mean alpha, smallest dihedral, share under 10 degrees, our
//    optimisation's share of our time; a CSV (generate_hxt.csv) and its plot (generate_hxt.png,
//    through plot_hxt.py: the times and the peak memory side by side) in OUT_DIR.
#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <spawn.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <regex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "bisect/io.hpp"
#include "bisect/quality.hpp"
#include "tet/tet_complex.hpp"

extern char** environ;

using namespace bisect;
namespace fs = std::filesystem;

namespace {

struct Run {
  bool ok = false;
  double wall = 0, peak_mb = 0;
  std::string out;  // stdout and stderr
};

// The peak resident memory (VmHWM) of a running process, MB; 0 once it has gone.
double vm_hwm_mb(pid_t pid) {
  std::ifstream st("/proc/" + std::to_string(pid) + "/status");
  std::string line;
  while (std::getline(st, line))
    if (line.rfind("VmHWM:", 0) == 0) return std::atof(line.c_str() + 6) / 1024.0;
  return 0;
}

// Runs argv, capturing its output in a file; wall time, and the peak resident memory polled
// from /proc every 5 ms (wait4's ru_maxrss would report this bench's own size: a spawned child
// inherits its parent's high-water mark on Linux).
Run run(const std::vector<std::string>& argv, const fs::path& log) {
  Run r;
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&fa, 1, 2);
  pid_t pid;
  const auto t0 = std::chrono::steady_clock::now();
  if (posix_spawnp(&pid, args[0], &fa, nullptr, args.data(), environ) != 0) return r;
  int status = 0;
  while (waitpid(pid, &status, WNOHANG) == 0) {
    r.peak_mb = std::max(r.peak_mb, vm_hwm_mb(pid));
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  r.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.ok = WIFEXITED(status) && WEXITSTATUS(status) == 0;
  std::ifstream in(log);
  std::stringstream ss;
  ss << in.rdbuf();
  r.out = ss.str();
  posix_spawn_file_actions_destroy(&fa);
  return r;
}

// TetGen's .ele tetrahedra (numbered from 1) added to m; TetGen's corners run the other way round.
void read_tetgen_ele(std::istream& ele, TetMesh& m) {
  long ne, per, eattr;
  ele >> ne >> per >> eattr;
  for (long i = 0; i < ne; ++i) {
    long id, v[4], skip;
    ele >> id >> v[0] >> v[1] >> v[2] >> v[3];
    for (long k = 0; k < eattr; ++k) ele >> skip;
    const Index c[4] = {static_cast<Index>(v[0] - 1), static_cast<Index>(v[1] - 1), static_cast<Index>(v[3] - 1), static_cast<Index>(v[2] - 1)};
    m.add_tet(c);
  }
}

double json_number(const std::string& json, const std::string& key) {
  const auto at = json.find("\"" + key + "\":");
  if (at == std::string::npos) return NAN;
  return std::atof(json.c_str() + at + key.size() + 3);
}

struct Mesh {
  bool ok = false;
  long tets = 0;
  double seconds = 0, peak_mb = 0, alpha = 0, below10 = 0, dihedral_min = 0;
  double wall = 0;  // the whole process, reading and writing files included
};

void grade(const TetMesh& m, Mesh& out) {
  const QualitySummary q = summarize_quality(element_quality(m));
  out.tets = static_cast<long>(m.num_tets());
  out.alpha = q.alpha.mean;
  out.dihedral_min = q.dihedral_min.min;
  out.below10 = q.pct_dihedral_below_10;
  out.ok = true;
}

fs::path scratch() {
  const fs::path d = fs::temp_directory_path() / "bisect_bench_generate";
  fs::create_directories(d);
  return d;
}

std::string bisect_mesh() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  return (exe.parent_path().parent_path() / "bin" / "bisect-mesh").string();
}

// threads: bisect-mesh's --threads (0, its default: one per core)
Mesh ours(const std::string& input, long r, std::string* stats_json = nullptr, int threads = 0) {
  Mesh m;
  const fs::path out = scratch() / "ours.vtu", stats = scratch() / "ours.json";
  const Run run_ = run({bisect_mesh(), input, "-n", std::to_string(r), "-o", out.string(), "--stats", stats.string(), "--threads", std::to_string(threads)},
                       scratch() / "ours.log");
  if (!run_.ok) {
    std::fprintf(stderr, "bisect-mesh failed on %s: %s\n", input.c_str(), run_.out.c_str());
    return m;
  }
  std::ifstream s(stats);
  std::stringstream ss;
  ss << s.rdbuf();
  if (stats_json) *stats_json = ss.str();
  m.seconds = json_number(ss.str(), "total");
  m.wall = run_.wall;
  m.peak_mb = run_.peak_mb;
  grade(read_mesh(out.string()), m);
  return m;
}

// Gmsh on the STL: surfaces reclassified (40 degrees) and remeshed, then Delaunay 3D; the 3D
// stage's wall time from its log. One size correction towards `want` tetrahedra.
Mesh gmsh(const std::string& stl, long want, double volume) {
  Mesh m;
  const fs::path geo = scratch() / "g.geo", msh = scratch() / "g.msh";
  std::ofstream(geo) << "Merge \"" << stl << "\";\nClassifySurfaces{40*Pi/180, 1, 1, Pi};\nCreateGeometry;\n"
                     << "Surface Loop(1) = Surface{:};\nVolume(1) = {1};\n";
  double size = std::cbrt(6 * std::sqrt(2.0) * volume / static_cast<double>(want));
  for (int round = 0; round < 2; ++round) {
    const Run r = run({"gmsh", "-3", "-algo", "del3d", "-clmax", std::to_string(size), geo.string(), "-o", msh.string(), "-format", "msh2"},
                      scratch() / "g.log");
    if (!r.ok) return m;
    std::smatch match;
    if (!std::regex_search(r.out, match, std::regex("Done meshing 3D \\(Wall ([0-9.e+-]+)s"))) return m;
    m.seconds = std::atof(match[1].str().c_str());
    m.peak_mb = r.peak_mb;
    grade(read_mesh(msh.string()), m);
    size *= std::cbrt(static_cast<double>(m.tets) / static_cast<double>(want));
  }
  return m;
}

// Gmsh HXT on the B-rep, end to end as a user waits for it (reading, curves, surfaces, the
// parallel Delaunay volume and its optimisation): the whole process's wall time, on `threads`
// threads. The size is Gmsh's own from the model, scaled (-clscale) towards `want` tetrahedra
// twice.
Mesh gmsh_hxt(const std::string& brep, long want, int threads) {
  Mesh m;
  const fs::path msh = scratch() / "hxt.msh";
  double scale = 0.2;
  for (int round = 0; round < 3; ++round) {
    const Run r = run({"gmsh", "-3", "-algo", "hxt", "-nt", std::to_string(threads), "-clscale", std::to_string(scale), brep, "-o", msh.string(),
                       "-format", "msh2"},
                      scratch() / "hxt.log");
    if (!r.ok) return m;
    m.seconds = m.wall = r.wall;
    m.peak_mb = r.peak_mb;
    grade(read_mesh(msh.string()), m);
    if (m.tets <= 0) return Mesh{};
    if (std::abs(static_cast<double>(m.tets) / static_cast<double>(want) - 1) < 0.05) break;
    scale *= std::cbrt(static_cast<double>(m.tets) / static_cast<double>(want));
  }
  return m;
}

// TetGen on the same facets (written as .smesh): quality bound 1.414, volume bound from want.
Mesh tetgen(const PolyInput& in, long want, double volume) {
  Mesh m;
  const fs::path smesh = scratch() / "t.smesh";
  {
    std::ofstream f(smesh);
    f.precision(17);
    f << in.nodes.size() << " 3 0 0\n";
    for (std::size_t i = 0; i < in.nodes.size(); ++i) f << i + 1 << ' ' << in.nodes[i].x() << ' ' << in.nodes[i].y() << ' ' << in.nodes[i].z() << '\n';
    f << in.faces.size() << " 0\n";
    for (const PolyFace& face : in.faces) {
      f << face.nodes.size();
      for (Index v : face.nodes) f << ' ' << v + 1;
      f << '\n';
    }
    f << "0\n0\n";
  }
  double a = 1.6 * volume / static_cast<double>(want);
  for (int round = 0; round < 2; ++round) {
    const Run r = run({"tetgen", "-pq1.414a" + std::to_string(a) + "Q", smesh.string()}, scratch() / "t.log");
    if (!r.ok) return m;
    m.seconds = r.wall;
    m.peak_mb = r.peak_mb;
    TetMesh t;
    std::ifstream node(scratch() / "t.1.node"), ele(scratch() / "t.1.ele");
    long n, dim, attr, marks;
    node >> n >> dim >> attr >> marks;
    t.nodes.resize(n);
    for (long i = 0; i < n; ++i) {
      long id;
      double x, y, z, skip;
      node >> id >> x >> y >> z;
      for (long k = 0; k < attr + marks; ++k) node >> skip;
      t.nodes[id - 1] = Vec3(x, y, z);
    }
    read_tetgen_ele(ele, t);
    grade(t, m);
    a *= static_cast<double>(m.tets) / static_cast<double>(want);
  }
  return m;
}

std::string cell(const Mesh& m) {
  if (!m.ok) return "failed | - | - | - | - | -";
  char b[160];
  std::snprintf(b, sizeof b, "%ld | %.2f | %.0f | %.0f | %.3f | %.2f", m.tets, m.seconds, m.tets / m.seconds, m.peak_mb, m.alpha, m.below10);
  return b;
}


// n random points in the unit cube, with its corners first; triangulated by our insertion
// (min-max or Delaunay, each followed by the min-max transformations) or by TetGen.
std::vector<Vec3> random_points(int n, unsigned seed) {
  std::vector<Vec3> X = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.01, 0.99);
  for (int i = 0; i < n; ++i) X.push_back({u(rng), u(rng), u(rng)});
  return X;
}

TetMesh ours_on_points(const std::vector<Vec3>& X, bool delaunay) {
  tet::TetComplex cx(X);
  std::vector<tet::Tet> t = {{0, 1, 2, 6}, {0, 2, 3, 6}, {0, 3, 7, 6}, {0, 7, 4, 6}, {0, 4, 5, 6}, {0, 5, 1, 6}};
  for (tet::Tet& x : t)
    if (!tet::positive(X, x)) std::swap(x[0], x[1]);
  cx.build(t);
  Index last = 0;
  for (Index v = 8; v < static_cast<Index>(X.size()); ++v) {
    const auto made = delaunay ? cx.insert_delaunay(v, last) : cx.insert(v, last);
    if (made.empty()) continue;
    last = made.front();
    if (!delaunay) {
      std::vector<std::pair<Index, int>> q;
      for (Index m : made)
        for (int f = 0; f < 4; ++f) q.push_back({m, f});
      cx.improve(q, 1 << 30);
    }
  }
  cx.improve_all(1 << 30);
  TetMesh m;
  m.nodes = X;
  for (const tet::Tet& x : cx.tets()) m.add_tet(x.data());
  return m;
}

TetMesh tetgen_on_points(const std::vector<Vec3>& X) {
  const fs::path node = scratch() / "p.node";
  {
    std::ofstream f(node);
    f.precision(17);
    f << X.size() << " 3 0 0\n";
    for (std::size_t i = 0; i < X.size(); ++i) f << i + 1 << ' ' << X[i].x() << ' ' << X[i].y() << ' ' << X[i].z() << '\n';
  }
  TetMesh m;
  if (!run({"tetgen", "-Q", node.string()}, scratch() / "p.log").ok) return m;
  m.nodes = X;
  std::ifstream ele(scratch() / "p.1.ele");
  read_tetgen_ele(ele, m);
  return m;
}

}  // namespace

int main(int argc, char** argv) {
  const long max_r = argc > 1 ? std::atol(argv[1]) : 100000;
  const fs::path shared = fs::path(BISECT_SHARED_DIR);
  if (!fs::exists(shared / "models/stl/lug.stl")) {
    std::printf("../shared is not here: nothing to measure\n");
    return 0;
  }
  std::printf("## CPU seconds per stage (thesis Tables 8.2.1-8.2.3)\n\n");
  std::printf("| model | R | tets | init_geom | bisect | gen_nodes | gen_tets | optimize | total |\n|---|---|---|---|---|---|---|---|---|\n");
  for (const char* model : {"models/stl/box-cavity.stl", "examples/cube-cavity-adjacent-cube.poly", "models/stl/lug.stl"})
    for (long r = 1000; r <= max_r && r <= 100000; r *= 10) {
      std::string js;
      const Mesh m = ours((shared / model).string(), r, &js);
      if (!m.ok) continue;
      std::printf("| %s | %ld | %ld | %.4f | %.4f | %.3f | %.3f | %.3f | %.3f |\n", fs::path(model).filename().c_str(), r, m.tets,
                  json_number(js, "init_geom"), json_number(js, "bisect"), json_number(js, "gen_nodes"), json_number(js, "gen_tets"),
                  json_number(js, "optimize"), json_number(js, "total"));
      std::fflush(stdout);
    }
  // 8.3.1: the alpha distribution on the slender appendage at about 3,600 tetrahedra
  {
    const fs::path out = scratch() / "slender.vtu";
    const Run r = run({bisect_mesh(), (shared / "models/stl/slender-appendage.stl").string(), "-n", "3600", "-o", out.string()}, scratch() / "s.log");
    if (r.ok) {
      const TetMesh m = read_mesh(out.string());
      const QualitySummary q = summarize_quality(element_quality(m));
      std::printf("\n## Alpha distribution on the slender appendage (Table 8.3.1), %zu tetrahedra, mean %.4f\n\n| alpha from | to | share |\n|---|---|---|\n",
                  m.num_tets(), q.alpha.mean);
      const double w = (q.alpha.hi - q.alpha.lo) / static_cast<double>(q.alpha.histogram.size());
      for (std::size_t b = 0; b < q.alpha.histogram.size(); ++b)
        std::printf("| %.4f | %.4f | %.4f |\n", q.alpha.lo + b * w, q.alpha.lo + (b + 1) * w,
                    static_cast<double>(q.alpha.histogram[b]) / static_cast<double>(m.num_tets()));
    }
  }
  // 8.3.2-8.3.3: random points
  std::printf("\n## Random points in a cube (Tables 8.3.2-8.3.3): mean and histogram of the smallest solid angle (sr)\n\n");
  std::printf("| nodes | method | tets | mean | 0-0.1 | 0.1-0.2 | 0.2-0.3 | 0.3-0.4 | 0.4-0.6 |\n|---|---|---|---|---|---|---|---|---|\n");
  for (int n : {10, 110, 510, 1010, 2020, 4010}) {
    const std::vector<Vec3> X = random_points(n, 42u + static_cast<unsigned>(n));
    const std::pair<const char*, TetMesh> meshes[] = {
        {"min-max", ours_on_points(X, false)}, {"Delaunay + min-max", ours_on_points(X, true)}, {"TetGen Delaunay", tetgen_on_points(X)}};
    for (const auto& [name, m] : meshes) {
      if (m.num_tets() == 0) continue;
      std::vector<double> bins(5, 0);
      double mean = 0;
      for (std::size_t t = 0; t < m.num_tets(); ++t) {
        const double w = min_solid_angle(m.nodes[m.tet_node(t, 0)], m.nodes[m.tet_node(t, 1)], m.nodes[m.tet_node(t, 2)], m.nodes[m.tet_node(t, 3)]);
        mean += w;
        bins[w < 0.1 ? 0 : w < 0.2 ? 1 : w < 0.3 ? 2 : w < 0.4 ? 3 : 4] += 1;
      }
      const double k = static_cast<double>(m.num_tets());
      std::printf("| %d | %s | %zu | %.4f | %.3f | %.3f | %.3f | %.3f | %.3f |\n", n, name, m.num_tets(), mean / k, bins[0] / k, bins[1] / k,
                  bins[2] / k, bins[3] / k, bins[4] / k);
    }
  }
  // scaling on lug.stl
  {
    const std::string out_dir = argc > 2 ? argv[2] : ".";
    const std::string csv = out_dir + "/generate_scaling.csv";
    std::ofstream c(csv);
    c << "model,r,tets,total_s,gen_nodes_s,gen_tets_s\n";
    std::printf("\n## Scaling on lug.stl\n\n| R | tets | total s | gen_nodes s | gen_tets s |\n|---|---|---|---|---|\n");
    std::vector<double> xs, ys;
    for (long r : {1000L, 3000L, 10000L, 30000L, 100000L, 300000L, 1000000L, 3000000L, 5000000L}) {
      if (r > max_r) break;
      std::string js;
      const Mesh m = ours((shared / "models/stl/lug.stl").string(), r, &js);
      if (!m.ok) break;
      c << "lug.stl," << r << ',' << m.tets << ',' << json_number(js, "total") << ',' << json_number(js, "gen_nodes") << ','
        << json_number(js, "gen_tets") << '\n';
      std::printf("| %ld | %ld | %.3f | %.3f | %.3f |\n", r, m.tets, json_number(js, "total"), json_number(js, "gen_nodes"), json_number(js, "gen_tets"));
      std::fflush(stdout);
      if (m.tets >= 5000) xs.push_back(std::log(static_cast<double>(m.tets))), ys.push_back(std::log(json_number(js, "total")));
    }
    c.close();
    if (xs.size() >= 2) {
      double mx = 0, my = 0;
      for (std::size_t i = 0; i < xs.size(); ++i) mx += xs[i] / xs.size(), my += ys[i] / ys.size();
      double sxy = 0, sxx = 0;
      for (std::size_t i = 0; i < xs.size(); ++i) sxy += (xs[i] - mx) * (ys[i] - my), sxx += (xs[i] - mx) * (xs[i] - mx);
      std::printf("\nfitted: total time ~ tets^%.2f (from 5,000 tetrahedra up)\n", sxy / sxx);
    }
    const std::string cmd = "/usr/bin/python3 '" + std::string(BISECT_BENCH_DIR) + "/plot_generate.py' '" + csv + "' '" + out_dir + "/generate_scaling.png'";
    if (std::system(cmd.c_str()) == 0) std::printf("plot: %s/generate_scaling.png\n", out_dir.c_str());
  }
  std::printf("\n## Beside Gmsh (3D stage) and TetGen, same run\n\n");
  std::printf("Ours on every core (the default) and on one thread (--threads 1; the same mesh), Gmsh on one.\n\n");
  std::printf("| model | R | ours tets | s | tets/s | MB | alpha | %% <10 | Gmsh tets | s | tets/s | MB | alpha | %% <10 | "
              "TetGen tets | s | tets/s | MB | alpha | %% <10 | ours 1 thread s | time / Gmsh | 1 thread / Gmsh |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  struct Case {
    const char* model;
    long r;
  };
  std::vector<Case> cases = {{"lug", 100000}, {"flange", 100000}, {"plate-hole", 100000}, {"part", 100000}};
  if (max_r >= 1000000) cases.push_back({"lug", 1000000});
  for (const Case& c : cases) {
    if (c.r > max_r) continue;
    const std::string stl = (shared / "models/stl" / (std::string(c.model) + ".stl")).string();
    const PolyInput in = read_polyhedral(stl);
    const double volume = summarize(in).volume;
    const Mesh o = ours(stl, c.r), one = ours(stl, c.r, nullptr, 1), g = gmsh(stl, o.ok ? o.tets : c.r, volume),
               t = tetgen(in, o.ok ? o.tets : c.r, volume);
    auto ratio = [&](const Mesh& x) { return x.ok && g.ok ? std::to_string(x.seconds / g.seconds).substr(0, 5) : std::string("-"); };
    std::printf("| %s | %ld | %s | %s | %s | %s | %s | %s |\n", c.model, c.r, cell(o).c_str(), cell(g).c_str(), cell(t).c_str(),
                one.ok ? std::to_string(one.seconds).substr(0, 5).c_str() : "-", ratio(o).c_str(), ratio(one).c_str());
    std::fflush(stdout);
  }
  // the strongest peer: Gmsh HXT from the B-rep, end to end, at the same count
  {
    const std::string out_dir = argc > 2 ? argv[2] : ".";
    const std::string csv = out_dir + "/generate_hxt.csv";
    std::ofstream c(csv);
    c << "model,r,tets,s_2threads,s_1thread,peak_mb,alpha,dihedral_min,pct_below_10,optimize_share,gen_tets_s,optimize_s,"
         "hxt_tets,hxt_s,hxt_peak_mb,hxt_alpha,hxt_dihedral_min,hxt_pct_below_10,ratio\n";
    std::printf("\n## Beside Gmsh HXT (`-3 -algo hxt -nt 2`, from the B-rep, the whole process), same run\n\n");
    std::printf("Ours from the STL on 2 threads and on 1 (the same mesh), each the whole process's wall time as for HXT; optimize: its "
                "share of our --stats total.\n\n");
    std::printf("| model | R | ours tets | s | 1 thread s | MB | alpha | min dihedral | %% <10 | optimize | HXT tets | s | MB | alpha | "
                "min dihedral | %% <10 | ours / HXT |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    struct Peer {
      const char* stl;
      const char* brep;
      long r;
    };
    std::vector<Peer> peers = {{"lug", "lug.brep", 100000}, {"flange", "flange.brep", 100000}, {"plate-hole", "plate-hole.brep", 100000},
                               {"part", "cad/part.step", 100000}, {"lug", "lug.brep", 1000000}, {"flange", "flange.brep", 1000000},
                               {"part", "cad/part.step", 1000000}, {"lug", "lug.brep", 5000000}};
    for (const Peer& p : peers) {
      if (p.r > max_r) continue;
      const std::string stl = (shared / "models/stl" / (std::string(p.stl) + ".stl")).string();
      std::string js;
      const Mesh o = ours(stl, p.r, &js, 2), one = ours(stl, p.r, nullptr, 1);
      const Mesh h = gmsh_hxt((shared / "models" / p.brep).string(), o.ok ? o.tets : p.r, 2);
      const double share = o.ok ? json_number(js, "optimize") / json_number(js, "total") : NAN;
      char row[512];
      std::snprintf(row, sizeof row, "| %s | %ld | %ld | %.2f | %.2f | %.0f | %.4f | %.1f | %.3f | %.0f%% | %ld | %.2f | %.0f | %.4f | %.1f | %.3f | %.2f |",
                    p.stl, p.r, o.tets, o.wall, one.wall, o.peak_mb, o.alpha, o.dihedral_min, o.below10, 100 * share, h.tets, h.wall,
                    h.peak_mb, h.alpha, h.dihedral_min, h.below10, o.ok && h.ok ? o.wall / h.wall : NAN);
      std::printf("%s\n", row);
      std::fflush(stdout);
      c << p.stl << ',' << p.r << ',' << o.tets << ',' << o.wall << ',' << one.wall << ',' << o.peak_mb << ',' << o.alpha << ','
        << o.dihedral_min << ',' << o.below10 << ',' << share << ',' << json_number(js, "gen_tets") << ',' << json_number(js, "optimize") << ','
        << h.tets << ',' << h.wall << ',' << h.peak_mb << ',' << h.alpha << ',' << h.dihedral_min << ',' << h.below10 << ','
        << (o.ok && h.ok ? o.wall / h.wall : NAN) << '\n';
    }
    std::printf("csv: %s\n", csv.c_str());
    c.close();
    const std::string cmd = "/usr/bin/python3 '" + std::string(BISECT_BENCH_DIR) + "/plot_hxt.py' '" + csv + "' '" + out_dir + "/generate_hxt.png'";
    if (std::system(cmd.c_str()) == 0) std::printf("plot: %s/generate_hxt.png\n", out_dir.c_str());
  }
  return 0;
}
