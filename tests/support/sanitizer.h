// Whether this build runs under AddressSanitizer (the sanitizer suite of CI, .ci/sanitize). A few
// suites repeat one check many times to catch a rare event (a kill that lands mid-save, a search
// long enough to move every stage); under the sanitizer each repeat costs five to ten times as
// much, and what the sanitizer looks for (a bad address, undefined behaviour) shows in the first
// repeats as in the last, so there they repeat fewer times. The normal build runs them all.
#pragma once

namespace fieldsight::test {

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

/// `normal` repeats, or a quarter of them (at least one) under the sanitizer.
constexpr int repeats(int normal)
{
    return kUnderSanitizer ? (normal + 3) / 4 : normal;
}

} // namespace fieldsight::test
