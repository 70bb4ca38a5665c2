#include "visioncore/io/bhuman_log.h"

#include "visioncore/basics/atomic_file.h"

#include <opencv2/imgcodecs.hpp>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>

namespace fieldsight {
namespace {

std::vector<std::string> splitCsv(const std::string& line)
{
    std::vector<std::string> out;
    std::string field;
    std::istringstream in(line);
    while (std::getline(in, field, ','))
        out.push_back(field);
    if (!line.empty() && line.back() == ',')
        out.emplace_back();
    return out;
}

std::optional<double> number(std::string text)
{
    while (!text.empty() && (text.back() == '\r' || text.back() == ' '))
        text.pop_back();
    double value = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(value))
        return std::nullopt;
    return value;
}

} // namespace

std::optional<Horizon> horizonOfLine(PointF origin, PointF direction, int width)
{
    if (std::abs(direction.x) < 1e-6)
        return std::nullopt;
    const double slope = direction.y / direction.x;
    const Horizon h{origin.y - origin.x * slope, origin.y + (width - 1 - origin.x) * slope};
    if (!(std::abs(h.y_left) <= Horizon::kMaxRows && std::abs(h.y_right) <= Horizon::kMaxRows))
        return std::nullopt;
    return h;
}

bool isBhumanLogFolder(const std::string& folder)
{
    namespace fs = std::filesystem;
    std::error_code ec;
    return fs::is_regular_file(fs::path(folder) / "frames.csv", ec) &&
           fs::is_directory(fs::path(folder) / "frames_ycbcr", ec);
}

Result<BhumanLog> readBhumanLog(const std::string& folder)
{
    namespace fs = std::filesystem;
    const fs::path dir(folder);
    const std::string csv_path = (dir / "frames.csv").string();
    auto text = readWholeFile(csv_path);
    if (!text)
        return text.error();
    std::istringstream lines(text.value());
    std::string line;
    if (!std::getline(lines, line))
        return Error{csv_path + ": empty; expected a header line and one row a frame"};
    std::map<std::string, std::size_t> column;
    const std::vector<std::string> header = splitCsv(line);
    for (std::size_t i = 0; i < header.size(); ++i) {
        std::string name = header[i];
        while (!name.empty() && name.back() == '\r')
            name.pop_back();
        column.emplace(name, i);
    }
    const char* needed[] = {
        "frame",         "timestamp_ms", "cam_matrix_valid", "horizon_origin_x", "horizon_origin_y",
        "horizon_dir_x", "horizon_dir_y"};
    for (const char* name : needed)
        if (!column.count(name))
            return Error{csv_path + ": the header has no column '" + name + "'"};

    BhumanLog log;
    std::size_t line_number = 1;
    while (std::getline(lines, line)) {
        ++line_number;
        if (line.empty() || line == "\r")
            continue;
        const std::vector<std::string> fields = splitCsv(line);
        const auto value = [&](const char* name) -> Result<double> {
            const std::size_t c = column.at(name);
            const auto v = c < fields.size() ? number(fields[c]) : std::nullopt;
            if (!v)
                return Error{csv_path + ": line " + std::to_string(line_number) + ": " + name +
                             " is not a number"};
            return *v;
        };
        double v[7];
        for (int k = 0; k < 7; ++k) {
            auto read = value(needed[k]);
            if (!read)
                return read.error();
            v[k] = read.value();
        }
        if (v[0] < 0 || v[0] > 999999 || v[0] != std::floor(v[0]))
            return Error{csv_path + ": line " + std::to_string(line_number) +
                         ": frame must be a whole number from 0"};
        char name[32];
        std::snprintf(name, sizeof name, "f%03d.png", int(v[0]));
        LoggedFrame frame;
        frame.path = (dir / "frames_ycbcr" / name).string();
        std::error_code ec;
        if (!fs::is_regular_file(frame.path, ec))
            return Error{csv_path + ": line " + std::to_string(line_number) + ": its frame " +
                         frame.path + " is missing"};
        frame.timestamp_ms = v[1];
        if (log.frames.empty()) {
            const cv::Mat first = cv::imread(frame.path, cv::IMREAD_UNCHANGED);
            if (first.empty())
                return Error{frame.path + ": not a readable PNG"};
            log.width = first.cols;
            log.height = first.rows;
        }
        if (v[2] != 0)
            frame.horizon = horizonOfLine({v[3], v[4]}, {v[5], v[6]}, log.width);
        else
            ++log.invalid;
        log.frames.push_back(std::move(frame));
    }
    if (log.frames.empty())
        return Error{csv_path + ": no frame rows after the header"};
    std::error_code ec;
    if (fs::is_regular_file(dir / "coltable.c64", ec))
        log.colour_table = (dir / "coltable.c64").string();
    return log;
}

} // namespace fieldsight
