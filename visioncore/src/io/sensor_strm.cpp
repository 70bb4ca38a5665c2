// Reads only the "Horizon" entries of an original NUSensorsData text stream.
#include "io/sensor_strm.h"

#include "visioncore/basics/atomic_file.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <string_view>
#include <system_error>

namespace fieldsight::io {

namespace {

/// Splits on whitespace, with '[', ']' and ',' as tokens of their own.
std::vector<std::string_view> tokenize(std::string_view text)
{
    std::vector<std::string_view> tokens;
    std::size_t i = 0;
    while (i < text.size()) {
        const char c = text[i];
        if (std::isspace(static_cast<unsigned char>(c))) {
            ++i;
        } else if (c == '[' || c == ']' || c == ',') {
            tokens.push_back(text.substr(i, 1));
            ++i;
        } else {
            const std::size_t start = i;
            while (i < text.size() && !std::isspace(static_cast<unsigned char>(text[i])) &&
                   text[i] != '[' && text[i] != ']' && text[i] != ',')
                ++i;
            tokens.push_back(text.substr(start, i - start));
        }
    }
    return tokens;
}

std::optional<double> number(std::string_view token)
{
    double value = 0;
    const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (ec != std::errc() || end != token.data() + token.size())
        return std::nullopt;
    return value;
}

bool isFlag(std::string_view token)
{
    return token == "0" || token == "1";
}

} // namespace

std::optional<std::string> findSensorStrmFor(const std::string& image_strm)
{
    namespace fs = std::filesystem;
    const fs::path image(image_strm);
    std::string name = image.filename().string();
    std::string lower = name;
    std::transform(lower.begin(), lower.end(), lower.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    constexpr std::string_view kSuffix = "image.strm";
    std::string candidate = "sensor.strm";
    if (lower.size() >= kSuffix.size() &&
        lower.compare(lower.size() - kSuffix.size(), kSuffix.size(), kSuffix) == 0)
        candidate = name.substr(0, name.size() - kSuffix.size()) + "sensor.strm";
    std::error_code ec;
    const fs::path path = image.parent_path() / candidate;
    if (fs::is_regular_file(path, ec))
        return path.string();
    return std::nullopt;
}

Result<std::vector<std::optional<Horizon>>> readSensorHorizons(const std::string& path, int width,
                                                               std::size_t frames)
{
    auto text = readWholeFile(path);
    if (!text)
        return text.error();
    const std::vector<std::string_view> tokens = tokenize(text.value());

    // A sensor entry is "Horizon <time> <validFloat> <validVector> <validMatrix> <validString>
    // [A, B, C]"; in the id lists the name is followed by "," or "]", so it cannot match there.
    std::vector<std::optional<Horizon>> horizons;
    for (std::size_t i = 0; i + 6 < tokens.size() && horizons.size() < frames; ++i) {
        if (tokens[i] != "Horizon" || !number(tokens[i + 1]) || !isFlag(tokens[i + 2]) ||
            !isFlag(tokens[i + 3]) || !isFlag(tokens[i + 4]) || !isFlag(tokens[i + 5]))
            continue;
        const bool valid_vector = tokens[i + 3] == "1";
        std::vector<double> values;
        std::size_t j = i + 6;
        if (tokens[j] == "[") {
            for (++j; j < tokens.size() && tokens[j] != "]"; ++j)
                if (tokens[j] != ",")
                    if (const auto v = number(tokens[j]))
                        values.push_back(*v);
        }
        std::optional<Horizon> horizon;
        if (valid_vector && values.size() == 3 && std::abs(values[1]) > 1e-9) {
            const double a = values[0], b = values[1], c = values[2];
            const double last_x = std::max(0, width - 1);
            horizon = Horizon{c / b, (c - a * last_x) / b};
            if (!horizon->isPlausible()) // nearly vertical, or rows no camera sees: invalid
                horizon.reset();
        }
        horizons.push_back(horizon);
        i = j;
    }
    return horizons;
}

} // namespace fieldsight::io
