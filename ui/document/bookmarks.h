// Bookmarks of a stream: frames a user marked with a note, kept in a sidecar file beside the
// stream (fieldsight-bookmarks/1) so every session, and any tool, finds them.
#pragma once

#include "visioncore/basics/result.h"

#include <cstddef>
#include <string>
#include <vector>

namespace fieldsight::ui {

struct Bookmark
{
    std::size_t frame = 0; ///< frame index
    std::string name;      ///< the frame's name when it was marked
    std::string note;
    friend bool operator==(const Bookmark&, const Bookmark&) = default;
};

class Bookmarks
{
public:
    /// The sidecar of a stream: <folder>/bookmarks.json for a folder, <file>.bookmarks.json for a
    /// file; empty for a camera.
    static std::string sidecarPath(const std::string& stream);

    /// Reads `path`; a missing file is an empty list. Errors name the file and the problem.
    static Result<Bookmarks> load(const std::string& path);
    static Result<Bookmarks> fromJson(const std::string& text, const std::string& source);
    std::string toJson() const;
    Status save(const std::string& path) const; ///< atomic

    const std::vector<Bookmark>& list() const { return m_list; }
    /// Adds or replaces the bookmark of `mark.frame`; the list stays in frame order.
    void set(Bookmark mark);
    bool remove(std::size_t frame);
    const Bookmark* find(std::size_t frame) const;

private:
    std::vector<Bookmark> m_list;
};

} // namespace fieldsight::ui
