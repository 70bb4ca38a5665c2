// Ground-truth annotations (SPEC §5.2, fieldsight-annotations/1): per frame, the true percepts.
#pragma once

#include "visioncore/percepts/percept_set.h"
#include "visioncore/basics/result.h"

#include <cstddef>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace fieldsight {

/// What an annotator says about one true object beyond its geometry (optional fields of the
/// object in SPEC §5.2; only those that differ from the defaults are written).
struct ObjectFlags
{
    bool concealed = false;    ///< partly hidden or blurred: scored apart, a miss is no plain miss
    int track = 0;             ///< the same object over frames (0: none)
    bool keyframe = false;     ///< placed by hand as a keyframe of its track
    bool interpolate = true;   ///< (keyframes) the frames since the track's previous keyframe are
                               ///< interpolated
    bool interpolated = false; ///< made by interpolating between two keyframes of its track
    /// The object's keys this version does not read, as the text of a JSON object ("" none):
    /// written back after the known ones, so a newer file's fields survive a save. An edit of
    /// the object keeps them (they go with its flags).
    std::string unknown = {};

    bool isDefault() const { return *this == ObjectFlags{}; }
    friend bool operator==(const ObjectFlags&, const ObjectFlags&) = default;
};

struct FrameAnnotation
{
    bool done = false; ///< fully annotated: what is absent is truly absent
    PerceptSet truth;  ///< read and written with the percepts' truth keys ("field_boundary")
    /// By truth key, parallel to that kind's list in `truth` (a shorter list: the rest default).
    std::map<std::string, std::vector<ObjectFlags>, std::less<>> flags;
    /// Truth keys whose list is complete on this frame although the frame is not done: reviewed,
    /// and (when the list is empty) "nothing here".
    std::set<std::string, std::less<>> reviewed;
    /// The frame's keys this version does not read (a kind it does not know, another field), as
    /// the text of a JSON object ("" none): written back after the known ones.
    std::string unknown = {};

    ObjectFlags flagsOf(std::string_view truth_key, std::size_t index) const;
    /// Sets the flags of object `index` of kind `truth_key` (the list grows with defaults).
    void setFlags(std::string_view truth_key, std::size_t index, const ObjectFlags& f);
    /// Removes object `index`'s flags (the object was removed): later objects' move up.
    void eraseFlags(std::string_view truth_key, std::size_t index);
    /// The list of kind `truth_key` holds every true object: the frame is done or the kind
    /// reviewed.
    bool complete(std::string_view truth_key) const
    {
        return done || reviewed.find(truth_key) != reviewed.end();
    }
    /// The same truth (compared as JSON), flags (defaults trimmed) and marks.
    friend bool operator==(const FrameAnnotation& a, const FrameAnnotation& b);
};

/// Why `name` cannot be a frame's name in an annotations file (a frame is named by its file
/// name alone), or nothing: empty, "." or "..", a path separator ('/', '\\'), or a control
/// character (a NUL, a newline).
std::optional<std::string> frameNameProblem(const std::string& name);

/// A frame's name without its extension: annotations name frames by file ("frame_000000.png")
/// where a .strm of the same frames names them "frame_000000"; the two match by stem.
std::string frameStem(const std::string& name);

/// The largest annotations file read for a stream of `frames` frames (0: not known): 16 MiB and
/// 4 KiB a frame. The sample streams' take 0.8 to 1.4 KB a frame (a field boundary of a few dozen
/// points, posts, lines, a ball), so 16 MiB alone holds twice the paper's longest stream; parsed,
/// JSON takes 15 to 25 times its size in memory.
std::size_t maxAnnotationsBytes(std::size_t frames);

struct Annotations
{
    std::map<std::string, FrameAnnotation> frames; ///< by frame name
    /// The file's top-level keys other than "format" and "frames", as the text of a JSON object
    /// ("" none): written back after them.
    std::string unknown = {};

    /// Reads the lists of `kinds` (a pipeline's perceptKinds()); every other key of the file, a
    /// frame or an object is kept as it is (FrameAnnotation::unknown, ObjectFlags::unknown) and
    /// written back. A frame name frameNameProblem() refuses, or two names of one frame (the
    /// same frameStem(): "f.png" and "f"), is an Error naming the file and the name. A file
    /// over maxAnnotationsBytes(`frames`) is refused unread, and running out of memory is an
    /// Error naming the file. The text is parsed a frame at a time, so a file takes little more
    /// memory than its text and what is read from it.
    static Result<Annotations> load(const std::string& path,
                                    const std::vector<const PerceptKind*>& kinds,
                                    std::size_t frames = 0);
    static Result<Annotations> fromJson(const std::string& text, const std::string& source,
                                        const std::vector<const PerceptKind*>& kinds);
    /// Each frame's lists of `order` (a pipeline's perceptKinds()) first, in that order, then
    /// the rest, so the file does not depend on the order the lists were made in; then the keys
    /// kept unknown. Top level: "format", "frames", then the unknown keys.
    std::string toJson(const std::vector<const PerceptKind*>& order) const;
    /// The true percepts of every frame by frameStem(), to look frames of any stream up in.
    std::map<std::string, const PerceptSet*> truthByStem() const;
    Status save(const std::string& path,
                const std::vector<const PerceptKind*>& order) const; ///< atomic, as toJson
};

} // namespace fieldsight
