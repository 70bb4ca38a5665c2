#include "synth/output_folder.h"

#include "visioncore/basics/atomic_file.h"
#include "visioncore/basics/json_text.h"
#include "visioncore/basics/file_fingerprint.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <vector>

namespace fieldsight::synth {

namespace fs = std::filesystem;

namespace {

/// The names synth writes into its folder.
bool isSynthFile(const std::string& name)
{
    return name == "image.strm" || name == "default.lut" || name == "annotations.json" ||
           name == "stream.json" ||
           (name.rfind("frame_", 0) == 0 && name.size() > 10 &&
            name.compare(name.size() - 4, 4, ".png") == 0);
}

/// The regular files directly in `dir` by name (an Error names what cannot be listed).
Result<std::set<std::string>> filesIn(const fs::path& dir)
{
    std::set<std::string> names;
    std::error_code ec;
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
        names.insert(it->path().filename().string());
    if (ec)
        return Error{dir.string() + ": cannot list the folder: " + ec.message()};
    return names;
}

bool sameBytes(const fs::path& a, const fs::path& b)
{
    std::error_code ec;
    if (fs::file_size(a, ec) != fs::file_size(b, ec) || ec)
        return false;
    std::ifstream fa(a, std::ios::binary), fb(b, std::ios::binary);
    std::vector<char> ba(1 << 16), bb(1 << 16);
    while (fa && fb) {
        fa.read(ba.data(), std::streamsize(ba.size()));
        fb.read(bb.data(), std::streamsize(bb.size()));
        if (fa.gcount() != fb.gcount() ||
            !std::equal(ba.begin(), ba.begin() + fa.gcount(), bb.begin()))
            return false;
    }
    return fa.eof() && fb.eof();
}

/// "a, b and 3 more".
std::string someOf(const std::set<std::string>& names)
{
    std::string text;
    std::size_t shown = 0;
    for (const std::string& name : names) {
        if (shown == 3)
            return text + " and " + std::to_string(names.size() - shown) + " more";
        text += (shown++ ? ", " : "") + name;
    }
    return text;
}

} // namespace

OutputFolder::OutputFolder(fs::path dir) : m_dir(std::move(dir))
{
    std::error_code ec;
    m_exists = fs::exists(fs::symlink_status(m_dir, ec));
    m_empty = !m_exists || (fs::is_directory(m_dir, ec) && fs::is_empty(m_dir, ec));
    const fs::path record = m_dir / kRecordName;
    if (!m_exists || !fs::exists(fs::symlink_status(record, ec)))
        return;
    m_has_record = true;
    auto text = readWholeFile(record.string(), std::size_t(64) << 20);
    const auto json =
        text ? jsonOrDiscarded(text.value()) : nlohmann::json(nlohmann::json::value_t::discarded);
    const auto files = json.is_object() ? json.find("files") : json.end();
    if (!json.is_object() || files == json.end() || !files->is_object()) {
        m_record_problem = text ? "it is not a synth output record" : text.error().message;
        return;
    }
    // A file's hash, or (a run stopped while moving its files in) the old and the new one.
    for (const auto& [name, hashes] : files->items())
        for (const auto& hash : hashes.is_array() ? hashes : nlohmann::json::array({hashes}))
            if (hash.is_string())
                m_recorded[name].insert(hash.get<std::string>());
}

std::optional<std::string> OutputFolder::fileHash(const fs::path& file)
{
    const FileFingerprint print = fingerprintFile(file.string());
    std::ifstream readable(file, std::ios::binary);
    if (!print.exists || !readable)
        return std::nullopt;
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(print.hash));
    return std::string(text);
}

bool OutputFolder::isUnrecordedSynthOutput() const
{
    if (auto text = readWholeFile((m_dir / "stream.json").string()); text) {
        const auto manifest = jsonOrDiscarded(text.value());
        return manifest.is_object() && manifest.contains("generator");
    }
    auto names = filesIn(m_dir);
    return names &&
           names.value() == std::set<std::string>{"annotations.json", "default.lut", "image.strm"};
}

Status OutputFolder::refuse(const std::set<std::string>& changed,
                            const std::set<std::string>& foreign) const
{
    std::string why;
    if (!changed.empty())
        why = someOf(changed) + (changed.size() == 1 ? " was" : " were") +
              " changed since synth wrote " + (changed.size() == 1 ? "it" : "them");
    if (!foreign.empty())
        why += (why.empty() ? "" : "; ") + someOf(foreign) +
               (foreign.size() == 1 ? " is" : " are") + " not synth's own";
    return Error{m_dir.string() + ": " + why +
                 "; nothing was written (choose a new or empty folder, or move those files away)"};
}

Status OutputFolder::check(const std::set<std::string>& names) const
{
    std::error_code ec;
    if (!m_exists || m_empty)
        return {};
    if (!fs::is_directory(m_dir, ec))
        return Error{m_dir.string() + ": exists and is not a folder; nothing was written"};
    if (!m_record_problem.empty())
        return Error{(m_dir / kRecordName).string() + ": " + m_record_problem +
                     "; nothing was written (choose a new or empty folder)"};
    if (!m_has_record)
        return isUnrecordedSynthOutput()
                   ? Status{}
                   : Error{m_dir.string() +
                           ": the folder is not empty and is not an earlier synth output; "
                           "nothing was written (choose a new or empty folder)"};
    auto present = filesIn(m_dir);
    if (!present)
        return present.error();
    std::set<std::string> changed, foreign;
    for (const std::string& name : present.value()) {
        if (name == kRecordName)
            continue;
        const auto recorded = m_recorded.find(name);
        if (recorded == m_recorded.end()) {
            if (names.count(name))
                foreign.insert(name); // the user's, and the new stream would replace it
            continue;
        }
        const auto hash = fileHash(m_dir / name);
        if (!hash || !recorded->second.count(*hash))
            changed.insert(name);
    }
    if (!changed.empty() || !foreign.empty())
        return refuse(changed, foreign);
    return {};
}

Status OutputFolder::commit(const fs::path& staged, bool& refused)
{
    refused = false;
    auto incoming = filesIn(staged);
    if (!incoming)
        return incoming.error();
    if (Status s = check(incoming.value()); !s) {
        refused = true;
        return s;
    }
    std::error_code ec;
    fs::create_directories(m_dir, ec);
    if (ec || !fs::is_directory(m_dir))
        return Error{m_dir.string() + ": cannot create the folder: " +
                     (ec ? ec.message() : std::string("not a folder"))};
    auto present = filesIn(m_dir);
    if (!present)
        return present.error();
    std::set<std::string> stale; // the earlier run's files the new stream does not have
    if (!m_has_record && !m_empty) {
        // No record says what synth wrote: only files identical to the new ones are replaced,
        // and none of the earlier stream's is left behind or removed.
        std::set<std::string> changed;
        for (const std::string& name : present.value()) {
            if (incoming.value().count(name)) {
                if (!sameBytes(m_dir / name, staged / name))
                    changed.insert(name);
            } else if (isSynthFile(name)) {
                changed.insert(name);
            }
        }
        if (!changed.empty()) {
            refused = true;
            return Error{m_dir.string() + ": this earlier synth output has no " + kRecordName +
                         " to tell what changed since it was written, and " + someOf(changed) +
                         (changed.size() == 1 ? " differs" : " differ") +
                         " from the new stream; nothing was written (choose a new or empty "
                         "folder)"};
        }
    } else {
        for (const auto& [name, hashes] : m_recorded)
            if (!incoming.value().count(name) && present.value().count(name))
                stale.insert(name);
    }

    nlohmann::json record = {{"format", "fieldsight-synth-output/1"},
                             {"files", nlohmann::json::object()}};
    for (const std::string& name : incoming.value()) {
        const auto hash = fileHash(staged / name);
        if (!hash)
            return Error{(staged / name).string() + ": cannot be read back"};
        record["files"][name] = *hash;
    }
    // The record goes first, naming old and new files alike, so a run stopped half way still
    // finds every file it may replace; it is rewritten with the new files alone at the end.
    nlohmann::json both = record;
    for (const auto& [name, hashes] : m_recorded)
        for (const std::string& hash : hashes) {
            nlohmann::json& entry = both["files"][name];
            if (entry.is_null())
                entry = hash;
            else if (entry.is_string() && entry != hash)
                entry = nlohmann::json::array({entry, hash});
            else if (entry.is_array() && std::find(entry.begin(), entry.end(), hash) == entry.end())
                entry.push_back(hash);
        }
    if (Status s = writeFileAtomically((m_dir / kRecordName).string(), jsonText(both, 1) + "\n");
        !s)
        return s;
    for (const std::string& name : incoming.value()) {
        fs::rename(staged / name, m_dir / name, ec);
        if (ec)
            return Error{(m_dir / name).string() +
                         ": cannot move the new file in: " + ec.message()};
    }
    for (const std::string& name : stale)
        fs::remove(m_dir / name, ec);
    return writeFileAtomically((m_dir / kRecordName).string(), jsonText(record, 1) + "\n");
}

} // namespace fieldsight::synth
