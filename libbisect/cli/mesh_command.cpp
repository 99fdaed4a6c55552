// `bisect-mesh INPUT -o OUTPUT`: the generator's stages as far as they are built. Today that is
// the convex decomposition (--cells-only); asking for tetrahedra says plainly that the 3D
// generator is not there yet instead of writing something else.
#include <fstream>
#include <ostream>

#include "bisect/errors.hpp"
#include "bisect/io.hpp"
#include "bisect/polyhedral_model.hpp"
#include "commands.hpp"

namespace bisect::cli {
namespace {

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

}  // namespace

int run_mesh(const std::string& input, const MeshOptions& opt, std::ostream& out, std::ostream& err) {
  (void)err;
  if (opt.output.empty()) throw InputError("no output file given (-o OUTPUT)");
  if (!opt.cells_only)
    throw InputError("tetrahedral meshing is not available in this version; --cells-only writes the convex cells");
  if (!ends_with(opt.output, ".poly"))
    throw InputError(opt.output + ": --cells-only writes the thesis .poly format; name the output *.poly");
  const PolyInput in = read_polyhedral(input);
  const Decomposition d = decompose(in);
  write_cells_poly(d, opt.output);
  if (!opt.stats.empty()) {
    std::ofstream s(opt.stats);
    if (!s) throw InputError(opt.stats + ": cannot write");
    s << decompose_stats_json(d.stats) << '\n';
  }
  if (!opt.quiet)
    out << opt.output << ": " << d.cells.size() << " convex cells from " << in.regions.size() << " region(s) in "
        << d.stats.prepare_seconds + d.stats.bisect_seconds << " s\n";
  return 0;
}

}  // namespace bisect::cli
