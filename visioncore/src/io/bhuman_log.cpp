#include "visioncore/io/bhuman_log.h"

#include "visioncore/basics/atomic_file.h"
#include "io/frame_file_checks.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string_view>
#include <vector>

namespace fieldsight {
namespace {

/// The comma-separated fields of `line` (views into it).
void splitCsv(std::string_view line, std::vector<std::string_view>& out)
{
    out.clear();
    for (;;) {
        const auto comma = line.find(',');
        out.push_back(line.substr(0, comma));
        if (comma == std::string_view::npos)
            return;
        line.remove_prefix(comma + 1);
    }
}

std::optional<double> number(std::string_view text)
{
    while (!text.empty() && (text.back() == '\r' || text.back() == ' '))
        text.remove_suffix(1);
    double value = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(value))
        return std::nullopt;
    return value;
}

/// Why `path` is no frame file to read, or nothing: missing, or not a regular file after links.
std::optional<std::string> notAFrameFile(const std::string& path)
{
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (status.type() == fs::file_type::not_found)
        return "is missing";
    if (ec)
        return "cannot be read: " + ec.message();
    switch (status.type()) {
    case fs::file_type::regular:
        return std::nullopt;
    case fs::file_type::directory:
        return "is a folder, not a regular file";
    case fs::file_type::fifo:
        return "is a FIFO, not a regular file";
    case fs::file_type::socket:
        return "is a socket, not a regular file";
    case fs::file_type::block:
    case fs::file_type::character:
        return "is a device, not a regular file";
    default:
        return "is not a regular file";
    }
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
    const auto text = readWholeFile(csv_path);
    if (!text)
        return text.error();
    // Lines are read in place (views into the text): the file is held once, not copied.
    std::string_view rest = text.value();
    if (rest.starts_with("\xEF\xBB\xBF")) // a UTF-8 byte order mark (a spreadsheet writes one)
        rest.remove_prefix(3);
    const auto nextLine = [&rest](std::string_view& line) {
        if (rest.empty())
            return false;
        const auto end = rest.find('\n');
        line = rest.substr(0, end);
        rest = end == std::string_view::npos ? std::string_view() : rest.substr(end + 1);
        if (line.ends_with('\r'))
            line.remove_suffix(1);
        return true;
    };
    std::string_view line;
    if (!nextLine(line))
        return Error{csv_path + ": empty; expected a header line and one row a frame"};
    std::map<std::string, std::size_t, std::less<>> column;
    std::vector<std::string_view> fields;
    splitCsv(line, fields);
    for (std::size_t i = 0; i < fields.size(); ++i)
        column.emplace(std::string(fields[i]), i);
    const char* needed[] = {
        "frame",         "timestamp_ms", "cam_matrix_valid", "horizon_origin_x", "horizon_origin_y",
        "horizon_dir_x", "horizon_dir_y"};
    std::size_t at[7];
    for (int k = 0; k < 7; ++k) {
        const auto it = column.find(needed[k]);
        if (it == column.end())
            return Error{csv_path + ": the header has no column '" + needed[k] + "'"};
        at[k] = it->second;
    }

    BhumanLog log;
    std::map<int, std::size_t> line_of; ///< the frames read, by number: their line
    std::optional<io::HeaderSize> size;
    std::size_t line_number = 1;
    while (nextLine(line)) {
        ++line_number;
        if (line.empty())
            continue;
        const std::string where = csv_path + ": line " + std::to_string(line_number) + ": ";
        splitCsv(line, fields);
        double v[7];
        for (int k = 0; k < 7; ++k) {
            const auto read = at[k] < fields.size() ? number(fields[at[k]]) : std::nullopt;
            if (!read)
                return Error{where + needed[k] + " is not a number"};
            v[k] = *read;
        }
        if (v[0] < 0 || v[0] > 999999 || v[0] != std::floor(v[0]))
            return Error{where + "frame must be a whole number from 0"};
        if (const auto [first, fresh] = line_of.emplace(int(v[0]), line_number); !fresh)
            return Error{where + "frame " + std::to_string(int(v[0])) + " again (line " +
                         std::to_string(first->second) + " has it already)"};
        char name[32];
        std::snprintf(name, sizeof name, "f%03d.png", int(v[0]));
        LoggedFrame frame;
        frame.path = (dir / "frames_ycbcr" / name).string();
        if (auto problem = notAFrameFile(frame.path))
            return Error{where + "its frame " + frame.path + " " + *problem};
        // Every frame decodes whole at the first one's size, or the stream made would fail
        // later, in `eval` or the window, far from the log.
        const auto pixels = io::decodeImageFile(frame.path, size);
        if (!pixels)
            return Error{where + "its frame: " + pixels.error().message};
        if (!size) {
            size = io::HeaderSize{pixels.value().cols, pixels.value().rows};
            log.width = pixels.value().cols;
            log.height = pixels.value().rows;
        }
        frame.timestamp_ms = v[1];
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
