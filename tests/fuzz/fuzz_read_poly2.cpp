// libFuzzer target: the .poly2 reader (bisect::read_poly2 on an in-memory stream). A refusal
// (InputError) is fine; any other exception, signal or sanitizer report is a finding.
#include "bisect/io.hpp"
#include "fuzz_guard.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return bisect::fuzz::guarded([&] {
    std::istringstream in(bisect::fuzz::as_string(data, size));
    (void)bisect::read_poly2(in, "fuzz.poly2");
  });
}
