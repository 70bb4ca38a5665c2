#include "ui/document/bookmarks.h"

#include "visioncore/basics/json_text.h"
#include "visioncore/basics/atomic_file.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace fieldsight::ui {

namespace {
constexpr const char* kFormat = "fieldsight-bookmarks/1";
}

std::string Bookmarks::sidecarPath(const std::string& stream)
{
    if (stream.empty() || stream.rfind("camera:", 0) == 0)
        return {};
    std::error_code ec;
    if (std::filesystem::is_directory(stream, ec))
        return (std::filesystem::path(stream) / "bookmarks.json").string();
    return stream + ".bookmarks.json";
}

Result<Bookmarks> Bookmarks::load(const std::string& path)
{
    std::error_code ec;
    if (!std::filesystem::exists(path, ec))
        return Bookmarks{};
    // The kind and size checks of every read: a FIFO sidecar must not hang the window. A
    // bookmark and its note take under 100 bytes: 4 MiB is tens of thousands of them.
    constexpr std::size_t kMaxBytes = std::size_t(4) << 20;
    return readingWithinMemory(path, [&]() -> Result<Bookmarks> {
        auto text = readWholeFile(path, kMaxBytes, "a bookmarks file");
        if (!text)
            return text.error();
        return fromJson(text.value(), path);
    });
}

Result<Bookmarks> Bookmarks::fromJson(const std::string& text, const std::string& source)
{
    auto parsed = parseJson(text, source);
    if (!parsed)
        return parsed.error();
    const nlohmann::json doc = std::move(parsed).value();
    if (!doc.is_object())
        return Error{source + ": not a JSON object"};
    // Not doc.value("format", ...): that throws when "format" is not a string.
    if (const auto format = doc.find("format");
        format == doc.end() || !format->is_string() || format->get<std::string>() != kFormat)
        return Error{source + ": format must be \"" + kFormat + "\""};
    const auto list = doc.find("bookmarks");
    if (list == doc.end() || !list->is_array())
        return Error{source + ": bookmarks must be an array"};
    Bookmarks marks;
    for (std::size_t i = 0; i < list->size(); ++i) {
        const auto& b = (*list)[i];
        const std::string where = source + ": bookmarks[" + std::to_string(i) + "]";
        if (!b.is_object() || !b.contains("frame") || !b["frame"].is_number_unsigned())
            return Error{where + ".frame must be a frame index (0 or more)"};
        Bookmark mark;
        mark.frame = b["frame"].get<std::size_t>();
        if (b.contains("name") && b["name"].is_string())
            mark.name = b["name"].get<std::string>();
        if (b.contains("note")) {
            if (!b["note"].is_string())
                return Error{where + ".note must be a string"};
            mark.note = b["note"].get<std::string>();
        }
        marks.set(std::move(mark));
    }
    return marks;
}

std::string Bookmarks::toJson() const
{
    nlohmann::ordered_json doc;
    doc["format"] = kFormat;
    doc["bookmarks"] = nlohmann::ordered_json::array();
    for (const Bookmark& b : m_list)
        doc["bookmarks"].push_back({{"frame", b.frame}, {"name", b.name}, {"note", b.note}});
    return jsonText(doc, 1) + "\n";
}

Status Bookmarks::save(const std::string& path) const
{
    const std::string text = toJson();
    return writeFileAtomically(path, text.data(), text.size());
}

void Bookmarks::set(Bookmark mark)
{
    const auto it = std::lower_bound(m_list.begin(), m_list.end(), mark.frame,
                                     [](const Bookmark& b, std::size_t f) { return b.frame < f; });
    if (it != m_list.end() && it->frame == mark.frame)
        *it = std::move(mark);
    else
        m_list.insert(it, std::move(mark));
}

bool Bookmarks::remove(std::size_t frame)
{
    const auto it = std::find_if(m_list.begin(), m_list.end(),
                                 [&](const Bookmark& b) { return b.frame == frame; });
    if (it == m_list.end())
        return false;
    m_list.erase(it);
    return true;
}

const Bookmark* Bookmarks::find(std::size_t frame) const
{
    for (const Bookmark& b : m_list)
        if (b.frame == frame)
            return &b;
    return nullptr;
}

} // namespace fieldsight::ui
