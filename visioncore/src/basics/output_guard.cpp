#include "visioncore/basics/output_guard.h"

#include "visioncore/basics/atomic_file.h"
#include "visioncore/basics/json_text.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <optional>

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

bool isImageFileName(const std::filesystem::path& name)
{
    std::string ext = name.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return ext == ".png" || ext == ".jpg" || ext == ".jpeg" || ext == ".bmp";
}

bool isStreamFolder(const std::filesystem::path& folder)
{
    std::error_code ec;
    if (std::filesystem::exists(folder / "stream.json", ec))
        return true;
    for (std::filesystem::directory_iterator it(folder, ec), end; !ec && it != end;
         it.increment(ec)) {
        const std::filesystem::path& name = it->path();
        if (name.extension() == ".strm" || isImageFileName(name))
            return true;
    }
    return false;
}

namespace {

/// What is at `path` (after links), or nothing when nothing is there.
std::optional<std::filesystem::file_status> existing(const std::string& path)
{
    std::error_code ec;
    const auto status = std::filesystem::status(path, ec);
    if (!std::filesystem::exists(status))
        return std::nullopt;
    return status;
}

/// The largest existing output file read to tell what it is (a results file of the paper's
/// longest stream is a few MiB).
constexpr std::size_t kLargestRecognised = std::size_t(64) << 20;

/// What the existing regular file at `path` is, in words, when it is not `kind`; empty when it is.
std::string whyNotOfKind(const std::string& path, const OutputFileKind& kind)
{
    std::error_code ec;
    const auto size = std::filesystem::file_size(path, ec);
    if (ec)
        return "cannot be read: " + ec.message();
    if (kind.table)
        return size == std::uintmax_t(128) * 128 * 128 ? std::string()
                                                       : "is not a colour table (.lut)";
    if (size > kLargestRecognised)
        return "is not an earlier output of this command (" + std::to_string(size) + " bytes)";
    auto text = readWholeFile(path, kLargestRecognised);
    if (!text)
        return "cannot be read";
    const auto json = jsonOrDiscarded(text.value());
    if (!json.is_object())
        return "is not an earlier output of this command (not a JSON object)";
    if (!kind.json_format.empty()) {
        const auto format = json.find("format");
        if (format != json.end() && format->is_string() &&
            format->get<std::string>() == kind.json_format)
            return {};
        const std::string other =
            format != json.end() && format->is_string() ? format->get<std::string>() : "";
        return "is not " + kind.json_format + (other.empty() ? "" : " (it is " + other + ")");
    }
    if (!kind.json_key.empty() && json.contains(kind.json_key))
        return {};
    return "is not an earlier output of this command";
}

} // namespace

Status checkOutputFile(std::string_view who, const std::string& output,
                       const std::vector<std::string>& inputs, const OutputFileKind& kind)
{
    if (output.empty() || output == "-")
        return {};
    if (Status s = checkNotAnInput(who, output, inputs); !s)
        return s;
    const auto status = existing(output);
    if (!status)
        return {};
    const std::string prefix = std::string(who) + ": the output " + output + " ";
    const std::string keep = "; nothing was written (choose a new file name)";
    if (std::filesystem::is_directory(*status))
        return Error{prefix + "is a folder" + keep};
    if (!std::filesystem::is_regular_file(*status))
        return {}; // a device or a pipe (/dev/stdout) is written to, never replaced
    const std::filesystem::path folder = resolvedPath(output).parent_path();
    if (!kind.report && isStreamFolder(folder))
        return Error{prefix + "would replace a file of the stream in " + folder.string() + keep};
    if (const std::string why = whyNotOfKind(output, kind); !why.empty())
        return Error{prefix + "exists and " + why + keep};
    return {};
}

Status checkRenderFolder(std::string_view who, const std::string& folder,
                         const std::vector<std::string>& inputs)
{
    if (Status s = checkNotAnInput(who, folder, inputs); !s)
        return s;
    const auto status = existing(folder);
    if (!status)
        return {};
    if (!std::filesystem::is_directory(*status))
        return Error{std::string(who) + ": " + folder + " is not a folder; nothing was written"};
    std::error_code ec;
    if (std::filesystem::exists(std::filesystem::path(folder) / kRenderMarker, ec))
        return {};
    return checkNewOrEmptyFolder(who, folder);
}

} // namespace fieldsight
