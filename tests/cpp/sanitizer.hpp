// Whether this test binary is built with AddressSanitizer (scripts/sanitize.sh, part of CI): the
// tests whose cost is many repetitions of one code path run fewer of them there, and timing
// bounds scale by the sanitizer's slowdown. The ordinary build runs them in full.
#pragma once

namespace bisect::test {

#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kUnderSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool kUnderSanitizer = true;
#else
inline constexpr bool kUnderSanitizer = false;
#endif
#else
inline constexpr bool kUnderSanitizer = false;
#endif

// how much slower than the release build a test runs (timing bounds scale by it)
inline constexpr double kSanitizerSlowdown = kUnderSanitizer ? 4 : 1;

}  // namespace bisect::test
