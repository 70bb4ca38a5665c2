// Colour class names and display colours (SPEC §1).
#include "visioncore/basics/colour.h"

#include <cctype>
#include <string>

namespace fieldsight {

namespace {

struct ColourEntry
{
    std::string_view name;         ///< SPEC snake-case name
    std::string_view display_name; ///< the original system's string, as in its LUT editor
    Rgb rgb;
};

constexpr std::array<ColourEntry, kColourCount> kColours{{
    {"unclassified", "unclassified", {0, 0, 0}},
    {"white", "white", {255, 255, 255}},
    {"green", "green", {0, 255, 0}},
    {"shadow_object", "shadow object", {168, 168, 168}},
    {"pink", "pink", {255, 20, 127}},
    {"pink_orange", "pink - orange", {255, 128, 128}},
    {"orange", "orange", {255, 165, 0}},
    {"yellow_orange", "yellow - orange", {238, 219, 83}},
    {"yellow", "yellow", {255, 255, 0}},
    {"blue", "blue", {0, 0, 255}},
    {"shadow_blue", "shadow blue", {25, 25, 112}},
}};

bool equalsIgnoringCase(std::string_view a, std::string_view b)
{
    if (a.size() != b.size())
        return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (std::tolower(static_cast<unsigned char>(a[i])) !=
            std::tolower(static_cast<unsigned char>(b[i])))
            return false;
    return true;
}

std::string_view trimmed(std::string_view s)
{
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front())))
        s.remove_prefix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back())))
        s.remove_suffix(1);
    return s;
}

} // namespace

std::string_view colourName(Colour colour)
{
    const auto id = std::size_t(colour);
    return id < kColours.size() ? kColours[id].name : std::string_view("invalid");
}

std::optional<Colour> colourFromName(std::string_view name)
{
    name = trimmed(name);
    for (std::size_t id = 0; id < kColours.size(); ++id)
        if (equalsIgnoringCase(name, kColours[id].name) ||
            equalsIgnoringCase(name, kColours[id].display_name))
            return Colour(id);
    return std::nullopt;
}

Rgb colourDisplayRgb(Colour colour)
{
    const auto id = std::size_t(colour);
    return id < kColours.size() ? kColours[id].rgb : Rgb{};
}

} // namespace fieldsight
