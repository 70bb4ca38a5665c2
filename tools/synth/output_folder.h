// The folder synth writes a stream into, and what it wrote there before: a record of every file
// it wrote with a hash of its bytes, so a later run replaces only what nobody changed since and
// never touches a file of the user's.
#pragma once

#include "visioncore/basics/result.h"

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <string>

namespace fieldsight::synth {

class OutputFolder
{
public:
    /// The record synth leaves beside the files it wrote (docs/formats.md).
    static constexpr const char* kRecordName = "synth-output.json";

    explicit OutputFolder(std::filesystem::path dir);

    /// Before anything is generated: may a stream of the files `names` be written here? A new or
    /// empty folder may; so may synth's own earlier output, when every file it recorded is
    /// unchanged and no file of the user's has one of `names`. A stream synth wrote before it
    /// kept a record (its stream.json names the generator) is decided by commit(), which sees
    /// the new bytes. Anything else is an Error naming the folder and what is in the way; nothing
    /// is written or removed.
    Status check(const std::set<std::string>& names) const;

    /// Moves the files of the folder `staged` (generated whole beside) in: check() again, and for
    /// a stream without a record, every file of it the new one would replace or leave behind must
    /// be byte for byte what is staged. Then each file is renamed into place, the earlier run's
    /// files the new one does not have are removed, and the record is written last. On an Error
    /// nothing in the folder was touched; `refused` says whether it was the folder's content
    /// (bad input) rather than the system.
    Status commit(const std::filesystem::path& staged, bool& refused);

    /// A 64-bit FNV-1a hash of the file's bytes, as 16 hex digits; nullopt when it cannot be read.
    static std::optional<std::string> fileHash(const std::filesystem::path& file);

private:
    /// Files a stream synth wrote before it kept a record: its stream.json names the generator,
    /// or (frames only in image.strm) it holds exactly image.strm, annotations.json, default.lut.
    bool isUnrecordedSynthOutput() const;
    Status refuse(const std::set<std::string>& changed, const std::set<std::string>& foreign) const;

    std::filesystem::path m_dir;
    bool m_exists = false;
    bool m_empty = true;
    bool m_has_record = false;
    std::map<std::string, std::set<std::string>> m_recorded; ///< file name -> hash(es) written
    std::string m_record_problem;                            ///< why the record could not be read
};

} // namespace fieldsight::synth
