#include "visioncore/basics/output_guard.h"

#include <filesystem>

namespace fieldsight {

namespace {

/// `path` made absolute, with links and `..` resolved as far as it exists.
std::filesystem::path resolvedPath(const std::string& path)
{
    std::error_code ec;
    const std::filesystem::path absolute = std::filesystem::absolute(path, ec);
    if (ec)
        return std::filesystem::path(path).lexically_normal();
    const std::filesystem::path resolved = std::filesystem::weakly_canonical(absolute, ec);
    return ec ? absolute.lexically_normal() : resolved;
}

/// `path` is `folder` or inside it.
bool isWithin(const std::filesystem::path& path, const std::filesystem::path& folder)
{
    auto p = path.begin();
    for (const auto& part : folder) {
        if (part.empty())
            continue; // a trailing separator
        if (p == path.end() || *p != part)
            return false;
        ++p;
    }
    return true;
}

} // namespace

Status checkNotAnInput(std::string_view command, const std::string& output,
                       const std::vector<std::string>& inputs)
{
    if (output.empty() || output == "-")
        return {};
    const std::filesystem::path out = resolvedPath(output);
    for (const std::string& input : inputs) {
        if (input.empty() || input == "-" || input.rfind("camera:", 0) == 0)
            continue;
        const std::filesystem::path in = resolvedPath(input);
        std::error_code ec;
        const bool same = out == in;
        // A new file beside a stream's frames is fine (results, samples, a table); replacing
        // one of its files is not.
        const bool replaces = std::filesystem::is_directory(in, ec) && isWithin(out, in) &&
                              std::filesystem::exists(out, ec) &&
                              !std::filesystem::is_directory(out, ec);
        if (same || replaces)
            return Error{std::string(command) + ": the output " + output + " (" + out.string() +
                         (same ? ") is the input " : ") would replace a file of the input ") +
                         input + " (" + in.string() + "); nothing was written"};
    }
    return {};
}

Status checkNewOrEmptyFolder(std::string_view who, const std::string& folder)
{
    std::error_code ec;
    const auto status = std::filesystem::status(folder, ec);
    if (!std::filesystem::exists(status))
        return {};
    if (!std::filesystem::is_directory(status))
        return Error{std::string(who) + ": " + folder + " is not a folder; nothing was written"};
    std::filesystem::directory_iterator it(folder, ec);
    if (ec)
        return Error{std::string(who) + ": " + folder + ": " + ec.message()};
    if (it != std::filesystem::directory_iterator())
        return Error{std::string(who) + ": " + folder + " is not empty (it has " +
                     it->path().filename().string() +
                     "); choose a new or empty folder, so nothing there is written over"};
    return {};
}

} // namespace fieldsight
