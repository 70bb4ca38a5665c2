// Small helpers shared by the batch commands: error lines, rounding for JSON, writing outputs.
#pragma once

#include "visioncore/atomic_file.h"
#include "visioncore/batch.h"
#include "visioncore/result.h"

#include <cmath>
#include <ostream>
#include <string>
#include <string_view>

namespace fieldsight::batch {

/// Rounds to `decimals` places so JSON shows 0.1234 rather than 0.12340000000000001.
inline double rounded(double value, int decimals)
{
    static constexpr double kScales[] = {1, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8};
    if (!std::isfinite(value) || decimals < 0 || decimals > 8)
        return value;
    const double scale = kScales[decimals];
    return std::round(value * scale) / scale;
}

/// Prints "fieldsight: <message>" as exactly one line.
inline void printError(std::ostream& err, std::string_view message)
{
    std::string line = "fieldsight: ";
    for (char c : message)
        line += (c == '\n' || c == '\r') ? ' ' : c;
    err << line << '\n' << std::flush;
}

/// Writes `text` to `path` atomically, or to `out` when `path` is "-".
inline Status writeOutput(const std::string& path, const std::string& text, std::ostream& out)
{
    if (path == "-") {
        out << text << std::flush;
        if (!out)
            return Error{"standard output: write failed"};
        return {};
    }
    return writeFileAtomically(path, text);
}

/// The end of a reporting command: prints `table` to `out`, then writes `json` to `json_path`
/// when one was given. Returns the command's exit code.
inline int finishReport(std::ostream& out, std::ostream& err, const std::string& table,
                        const std::string& json_path, const std::string& json)
{
    out << table << std::flush;
    if (!json_path.empty()) {
        if (Status s = writeOutput(json_path, json, out); !s) {
            printError(err, s.error().message);
            return kExitFailure;
        }
    }
    return kExitOk;
}

} // namespace fieldsight::batch
