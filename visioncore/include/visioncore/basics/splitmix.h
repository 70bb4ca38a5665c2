// SplitMix64 (Steele, Lea & Flood, 2014): a 64-bit hash and a tiny random engine built on it. The
// same numbers on every platform and standard library, and seeding costs nothing, so a stage can
// start from its seed on every frame.
#pragma once

#include <cstdint>
#include <limits>

namespace fieldsight {

inline constexpr std::uint64_t kGoldenGamma = 0x9E3779B97F4A7C15ull;

/// The SplitMix64 finaliser: related inputs give unrelated outputs.
constexpr std::uint64_t splitMix64(std::uint64_t z)
{
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

/// A UniformRandomBitGenerator of 32-bit values: a Weyl sequence through the finaliser.
class SplitMix64
{
public:
    using result_type = std::uint32_t;
    explicit SplitMix64(std::uint64_t seed) : m_state(seed) {}
    static constexpr result_type min() { return 0; }
    static constexpr result_type max() { return std::numeric_limits<result_type>::max(); }
    result_type operator()()
    {
        m_state += kGoldenGamma;
        return result_type(splitMix64(m_state) >> 32);
    }

private:
    std::uint64_t m_state;
};

} // namespace fieldsight
