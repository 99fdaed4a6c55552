// libFuzzer target: the whole 2D pipeline (the planar mesher of thesis ch. 4, mesh_planar) on
// small .poly2 inputs, with and without optimisation and quadrilaterals. Inputs over the limits
// below are skipped before meshing, so that a slow run means a hang, not a big request. A
// refusal (InputError, MeshingError) is fine; any other exception, signal, sanitizer report or
// timeout is a finding.
#include "bisect/io.hpp"
#include "fuzz_guard.hpp"
#include "mesh2d/planar_mesher.hpp"

namespace {

constexpr std::size_t kMaxNodeRefs = 400;        // node references over all polygons
constexpr std::int64_t kMaxElements = 500;       // R
constexpr std::int64_t kDefaultElements = 200;   // R when the file gives none or too many

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return bisect::fuzz::guarded([&] {
    std::istringstream in(bisect::fuzz::as_string(data, size));
    bisect::Poly2Input poly = bisect::read_poly2(in, "fuzz.poly2");
    std::size_t refs = 0;
    for (const auto& p : poly.polygons) refs += p.nodes.size();
    if (refs > kMaxNodeRefs) return;

    bisect::mesh2d::PlanarOptions opt;
    const std::int64_t r = poly.required_elements;
    opt.elements = (r > 0 && r <= kMaxElements) ? r : kDefaultElements;
    // the options chosen by the input's size, so that a run is reproducible from the file alone
    opt.optimize = size % 3 != 0;
    opt.quads = size % 2 == 1;
    (void)bisect::mesh2d::mesh_planar(poly, opt);
  });
}
