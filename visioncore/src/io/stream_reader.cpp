// openStream(): decides what a stream argument names and hands it to the matching reader.
#include "visioncore/io/stream_reader.h"

#include "io/stream_readers.h"
#include "visioncore/basics/atomic_file.h"

#include <opencv2/core/utils/logger.hpp>

#include <algorithm>
#include <cstdlib>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cstring>
#include <filesystem>

#include <sys/stat.h>

namespace fieldsight {

Status StreamReader::readInto(std::size_t index, Frame& frame)
{
    auto read = this->read(index);
    if (!read)
        return read.error();
    frame = std::move(read).value();
    return {};
}

std::string besideStream(const std::string& stream, const std::string& name)
{
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path path(stream);
    const fs::path folder = fs::is_directory(path, ec) ? path : path.parent_path();
    return (folder / name).string();
}

Result<std::unique_ptr<StreamReader>> StreamReader::reopen() const
{
    return io::openStored(info().path);
}

namespace io {

Result<Frame> InPlaceReader::read(std::size_t index)
{
    Frame frame;
    if (Status s = readInto(index, frame); !s)
        return s.error();
    return frame;
}

std::string indexedFrameName(std::size_t index)
{
    // "frame_%06zu" by hand: it is named once per frame read, and snprintf costs more than the
    // rest of the name.
    char digits[24];
    int n = 0;
    do {
        digits[n++] = char('0' + index % 10);
        index /= 10;
    } while (index > 0);
    std::string name = "frame_";
    name.append(std::size_t(n < 6 ? 6 - n : 0), '0');
    while (n > 0)
        name += digits[--n];
    return name;
}

} // namespace io

namespace {

std::string lowercase(std::string s)
{
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

} // namespace

Result<std::unique_ptr<StreamReader>> openStream(const std::string& spec,
                                                 const StreamOptions& options)
{
    auto stored = io::openStored(spec);
    if (!stored)
        return stored;
    std::unique_ptr<StreamReader> reader = std::move(stored).value();
    const Orientation orientation = options.orientation.value_or(reader->info().stream_orientation);
    if (orientation == Orientation::Upright)
        return reader;
    return io::orientReader(std::move(reader), orientation);
}

namespace io {
namespace {

/// The pixel ceiling is set before main, while the program has one thread: setenv while another
/// thread reads the environment (Qt does, painting text) can crash it.
[[maybe_unused]] const bool kPixelCeilingSet = [] {
    ::setenv("OPENCV_IO_MAX_IMAGE_PIXELS", std::to_string(8192LL * 8192LL).c_str(), 0);
    return true;
}();

} // namespace

ReaderResult openStored(const std::string& spec)
{
    // OpenCV's own ceiling on decoded pixels (1 Gpx by default) down to what a frame may be
    // (8192 x 8192), for images whose header this reader cannot read first; a user's setting
    // wins. Read by OpenCV at its first decode.
    // OpenCV's own log lines (GStreamer and FFmpeg warnings, "raised OpenCV exception" while
    // probing back ends) are silenced: the user sees Fieldsight's one line naming the file.
    static const bool capped = [] {
        cv::utils::logging::setLogLevel(cv::utils::logging::LOG_LEVEL_SILENT);
        return true;
    }();
    (void)capped;
    namespace fs = std::filesystem;
    if (spec.empty())
        return Error{"no stream given"};

    constexpr std::string_view kCameraPrefix = "camera:";
    if (spec.compare(0, kCameraPrefix.size(), kCameraPrefix) == 0) {
        const std::string number = spec.substr(kCameraPrefix.size());
        int device = -1;
        const auto [end, ec] =
            std::from_chars(number.data(), number.data() + number.size(), device);
        if (number.empty() || ec != std::errc() || end != number.data() + number.size() ||
            device < 0)
            return Error{spec + ": expected camera:N with N a camera number (0, 1, ...)"};
        return io::openCamera(device, spec);
    }

    // What the path names, by stat: a link loop, a name longer than the system allows or a
    // folder without permission is reported as what it is, not as a missing file; a FIFO or a
    // device is refused before anything opens it (opening a FIFO would wait for a writer).
    struct stat st
    {
    };
    if (::stat(spec.c_str(), &st) != 0) {
        const int error = errno;
        if (error == ENOENT || error == ENOTDIR)
            return Error{spec + ": no such file or folder"};
        return Error{"cannot open " + spec + ": " + std::strerror(error)};
    }
    if (S_ISDIR(st.st_mode))
        return io::openImageFolder(spec, spec);
    if (!S_ISREG(st.st_mode))
        return notARegularFile(spec, st.st_mode);
    if (lowercase(fs::path(spec).extension().string()) == ".strm")
        return io::openStrm(spec, spec);
    return io::openVideo(spec, spec);
}

} // namespace io

} // namespace fieldsight
