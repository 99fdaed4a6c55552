// libFuzzer target: the .msh tetrahedral mesh reader (meshio::read_msh, the stream overload that
// read_mesh dispatches to). A refusal (InputError) is fine; any other exception, signal or
// sanitizer report is a finding.
#include "fuzz_guard.hpp"
#include "io/mesh_formats.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return bisect::fuzz::guarded([&] {
    std::istringstream in(bisect::fuzz::as_string(data, size));
    (void)bisect::meshio::read_msh(in, "fuzz.msh");
  });
}
