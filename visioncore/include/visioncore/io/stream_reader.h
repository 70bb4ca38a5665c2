// Stream readers (SPEC §4): image folders with stream.json, NUbots .strm files, video files.
// Random access by frame index without loading the whole stream into memory.
#pragma once

#include "visioncore/io/frame.h"
#include "visioncore/io/orientation.h"
#include "visioncore/basics/result.h"

#include <array>
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace fieldsight {

enum class StreamKind { ImageFolder, Strm, Video, Camera };

struct StreamInfo
{
    std::string path; ///< as given by the user
    StreamKind kind = StreamKind::ImageFolder;
    int width = 0;  ///< px, of the first frame as served (upright)
    int height = 0; ///< px
    std::size_t frame_count = 0;
    std::string default_lut; ///< the manifest's lut or <folder>/default.lut; empty if none exists
    /// The stream's own stage parameters (the manifest's "params"), applied when it is opened;
    /// empty when it names none.
    std::string params;
    std::optional<std::array<double, 2>> fov_deg; ///< deg, horizontal and vertical
    /// What the reader skipped, one line each naming it (a frame entry that is a dangling link,
    /// a link loop, a FIFO): the stream opened without it. Commands print these, the window
    /// shows them.
    std::vector<std::string> warnings;
    /// How far the stored pictures are turned clockwise as they are read: the stream's own
    /// orientation, or the one asked for when it was opened.
    Orientation orientation = Orientation::Upright;
    /// What the stream itself says (its manifest's "orientation"; upright for other kinds).
    Orientation stream_orientation = Orientation::Upright;
};

/// How a stream is opened.
struct StreamOptions
{
    /// Turn the stored pictures by this instead of the stream's own orientation.
    std::optional<Orientation> orientation;
};

class StreamReader
{
public:
    virtual ~StreamReader() = default;
    virtual const StreamInfo& info() const = 0;
    /// Reads frame `index` (< frame_count). Errors name the file and the problem.
    virtual Result<Frame> read(std::size_t index) = 0;
    /// read() into `frame`, reusing its pixel buffer where the reader can (a .strm record is
    /// decoded in place), so a steady run allocates nothing per frame. On error `frame` is
    /// unspecified.
    virtual Status readInto(std::size_t index, Frame& frame);
    /// The frame's display name without decoding it.
    virtual std::string frameName(std::size_t index) const = 0;
    /// Another reader of the same stream, for another thread, serving the same frames (in the
    /// same orientation). The default opens the stream again; readers with an index share it
    /// instead of building it twice.
    virtual Result<std::unique_ptr<StreamReader>> reopen() const;
};

/// A file kept beside a stream: `name` in the stream's folder, or in the folder holding the
/// stream's file (annotations.json, lut_samples.json, ...).
std::string besideStream(const std::string& stream, const std::string& name);

/// Opens a folder, a .strm file, a video file or "camera:N". Bad input (missing, empty folder,
/// truncated .strm, bad manifest) gives an Error naming the file and the problem. Frames are
/// served turned upright by the stream's orientation, or by `options.orientation` when given
/// (docs/formats.md): pixels, size and horizon alike.
Result<std::unique_ptr<StreamReader>> openStream(const std::string& spec,
                                                 const StreamOptions& options = {});

/// Writes original NUbots image streams (.strm), for tests, the generator and conversions.
class StrmWriter
{
public:
    /// Truncates or creates `path`.
    static Result<StrmWriter> create(const std::string& path);
    /// Appends one record; with `flipped` the stored raster is the frame rotated 180 degrees.
    Status append(const Frame& frame, bool flipped = false);
    Status close();

private:
    explicit StrmWriter(std::string path) : m_path(std::move(path)) {}
    std::string m_path;
    std::vector<char> m_buffer;
    std::shared_ptr<void> m_file;
};

} // namespace fieldsight
