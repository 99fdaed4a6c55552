#include "pipeline/brep_closure.hpp"

#include <map>

#include "bisect/errors.hpp"

namespace bisect::pipeline {

void check_solids_closed(const BrepInput& in) {
  for (std::size_t s = 0; s < in.solids.size(); ++s) {
    std::map<Index, std::pair<int, Index>> uses;  // edge -> (uses, a face using it)
    for (Index f : in.solids[s].faces)
      for (const auto& wire : in.faces[f].wires)
        for (const BrepEdgeUse& u : wire) {
          if (in.edges[u.edge].degenerate) continue;
          auto& [n, face] = uses[u.edge];
          ++n, face = f;
        }
    for (const auto& [e, use] : uses)
      if (use.first < 2)
        throw InputError(in.source + ": " + solid_name(in, static_cast<Index>(s)) + " is not closed: " + edge_name(e) + " bounds only " +
                         face_name(use.second) + " (a solid needs every edge shared by two of its faces)");
  }
}

}  // namespace bisect::pipeline
