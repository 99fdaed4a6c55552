// libFuzzer target: the whole 3D pipeline (generate_mesh, orders 1 and 2) on small inputs. The
// input is read as STL when it looks like one (starts with "solid", or has the binary layout's
// exact size), else as .poly. Inputs over the limits below are skipped before meshing, so that
// every run stays short and a slow run means a hang, not a big request. A refusal (InputError,
// MeshingError) is fine; any other exception, signal, sanitizer report or timeout is a finding.
#include <cstring>

#include "bisect/generate.hpp"
#include "bisect/io.hpp"
#include "fuzz_guard.hpp"

namespace {

constexpr std::size_t kMaxFacets = 200;          // faces after reading (STL triangles, .poly faces)
constexpr std::size_t kMaxFaceNodes = 2000;      // node references over all faces
constexpr std::int64_t kMaxElements = 500;       // R
constexpr std::int64_t kDefaultElements = 200;   // R when the file gives none or too many

bool looks_like_stl(const std::string& s) {
  if (s.size() >= 84) {
    std::uint32_t n = 0;
    std::memcpy(&n, s.data() + 80, 4);
    if (84 + 50 * std::uint64_t(n) == s.size()) return true;
  }
  return s.compare(0, 5, "solid") == 0;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return bisect::fuzz::guarded([&] {
    const std::string text = bisect::fuzz::as_string(data, size);
    std::istringstream in(text);
    bisect::PolyInput poly = looks_like_stl(text) ? bisect::read_stl(in, "fuzz.stl")
                                                  : bisect::read_poly(in, "fuzz.poly");
    if (poly.faces.size() > kMaxFacets) return;
    std::size_t refs = 0;
    for (const auto& f : poly.faces) refs += f.nodes.size();
    if (refs > kMaxFaceNodes) return;

    bisect::GenerateOptions opt;
    const std::int64_t r = poly.required_elements;
    opt.sizing.elements = (r > 0 && r <= kMaxElements) ? r : kDefaultElements;
    opt.order = 1 + int(size % 2);  // both orders, chosen by the input so a run is reproducible
    opt.threads = 1;                // libFuzzer and the sanitizers see one thread's work
    (void)bisect::generate_mesh(poly, opt);
  });
}
