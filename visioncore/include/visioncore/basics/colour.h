// The colour classes of the original system (SPEC §1): ids, names and display colours.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

namespace fieldsight {

enum class Colour : std::uint8_t {
    Unclassified = 0,
    White = 1,
    Green = 2,
    ShadowObject = 3,
    Pink = 4,
    PinkOrange = 5,
    Orange = 6,
    YellowOrange = 7,
    Yellow = 8,
    Blue = 9,
    ShadowBlue = 10,
};

inline constexpr int kColourCount = 11;

struct Rgb
{
    std::uint8_t r = 0;
    std::uint8_t g = 0;
    std::uint8_t b = 0;
    friend bool operator==(const Rgb&, const Rgb&) = default;
};

/// Snake-case name as in SPEC §1 ("shadow_object").
std::string_view colourName(Colour colour);
/// Accepts the SPEC names and the original's display names ("shadow object", "pink - orange").
std::optional<Colour> colourFromName(std::string_view name);
Rgb colourDisplayRgb(Colour colour);
inline bool isValidColourId(int id)
{
    return id >= 0 && id < kColourCount;
}

} // namespace fieldsight
