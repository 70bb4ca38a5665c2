// Byte-stable random numbers for the scene generator: raw std::mt19937_64 output mapped by hand,
// because the std:: distributions are allowed to differ between standard libraries.
#pragma once

#include "visioncore/basics/splitmix.h"

#include <cmath>
#include <cstdint>
#include <random>

namespace fieldsight::synth {

/// Turns related inputs (seed, scenario, frame) into unrelated seeds (the SplitMix64 finaliser).
constexpr std::uint64_t mixSeed(std::uint64_t a, std::uint64_t b)
{
    return splitMix64(a + kGoldenGamma * (b + 1));
}

/// A value in [0, 1) that depends only on the integer lattice point (i, j) and `salt`: the basis
/// of the procedural textures, so a surface looks the same from every camera pose.
inline double latticeNoise(std::int64_t i, std::int64_t j, std::uint64_t salt)
{
    const std::uint64_t h = mixSeed(mixSeed(salt, std::uint64_t(i)), std::uint64_t(j));
    return double(h >> 11) * 0x1.0p-53;
}

/// Smooth value noise in [0, 1): bilinear between lattice values with smoothstep weights.
inline double valueNoise(double x, double y, std::uint64_t salt)
{
    const double fx = std::floor(x);
    const double fy = std::floor(y);
    const auto i = std::int64_t(fx);
    const auto j = std::int64_t(fy);
    double tx = x - fx;
    double ty = y - fy;
    tx = tx * tx * (3 - 2 * tx);
    ty = ty * ty * (3 - 2 * ty);
    const double a = latticeNoise(i, j, salt);
    const double b = latticeNoise(i + 1, j, salt);
    const double c = latticeNoise(i, j + 1, salt);
    const double d = latticeNoise(i + 1, j + 1, salt);
    return (a + (b - a) * tx) + ((c + (d - c) * tx) - (a + (b - a) * tx)) * ty;
}

class Rng
{
public:
    explicit Rng(std::uint64_t seed) : m_engine(seed) {}

    /// Uniform in [0, 1), from the top 53 bits of one engine output.
    double uniform() { return double(m_engine() >> 11) * 0x1.0p-53; }
    double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
    /// Uniform integer in [0, n).
    int below(int n) { return int(uniform() * n); }
    bool chance(double p) { return uniform() < p; }
    /// Standard normal (Box-Muller; the second value of each pair is kept for the next call).
    double normal()
    {
        if (m_has_spare) {
            m_has_spare = false;
            return m_spare;
        }
        const double u1 = 1.0 - uniform(); // (0, 1], so the log is finite
        const double u2 = uniform();
        const double r = std::sqrt(-2.0 * std::log(u1));
        const double a = 2.0 * 3.14159265358979323846 * u2;
        m_spare = r * std::sin(a);
        m_has_spare = true;
        return r * std::cos(a);
    }

private:
    std::mt19937_64 m_engine;
    double m_spare = 0;
    bool m_has_spare = false;
};

} // namespace fieldsight::synth
