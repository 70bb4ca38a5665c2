// Image-folder streams (SPEC §4): frames in natural file-name order plus an optional stream.json.
#include "io/stream_readers.h"

#include "io/file_names.h"
#include "io/frame_file_checks.h"
#include "io/nuview_folder.h"
#include "io/stream_manifest.h"
#include "visioncore/basics/atomic_file.h"
#include "visioncore/basics/output_guard.h"
#include "visioncore/basics/ycbcr.h"

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <memory>
#include <optional>
#include <system_error>
#include <unordered_map>
#include <vector>

#include <sys/stat.h>

namespace fieldsight::io {

namespace fs = std::filesystem;

namespace {

/// Why the folder entry `path`, named as a frame, is not one, or nullopt when it is a regular
/// file (after links): a dangling link, a link loop, a FIFO or a folder is skipped and reported.
std::optional<std::string> brokenFrameEntry(const std::string& path)
{
    struct stat st
    {
    };
    if (::stat(path.c_str(), &st) == 0)
        return S_ISREG(st.st_mode)
                   ? std::nullopt
                   : std::optional<std::string>(path + ": skipped, " + fileKindName(st.st_mode) +
                                                ", not a frame file");
    const int error = errno;
    if (error == ENOENT) // the entry is there, so it is a link whose target is not
        return path + ": skipped, a link to a file that does not exist";
    if (error == ELOOP)
        return path + ": skipped, a link loop (" + std::strerror(error) + ")";
    return path + ": skipped, " + std::strerror(error);
}

/// The reported entries, at most kMaxReported lines: a folder of thousands of broken links is
/// one message, not thousands.
std::vector<std::string> reported(std::vector<std::string> skipped)
{
    constexpr std::size_t kMaxReported = 10;
    if (skipped.size() > kMaxReported) {
        const std::size_t more = skipped.size() - (kMaxReported - 1);
        skipped.resize(kMaxReported - 1);
        skipped.push_back("and " + std::to_string(more) + " more entries skipped");
    }
    return skipped;
}

class ImageFolderReader final : public StreamReader
{
public:
    ImageFolderReader(StreamInfo info, fs::path folder, std::vector<std::string> files,
                      std::vector<FrameMeta> meta, PixelFormat format)
        : m_info(std::move(info)), m_folder(std::move(folder)), m_files(std::move(files)),
          m_meta(std::move(meta)), m_format(format)
    {
    }

    const StreamInfo& info() const override { return m_info; }
    std::string frameName(std::size_t index) const override
    {
        return index < m_files.size() ? m_files[index] : std::string();
    }

    Result<Frame> read(std::size_t index) override
    {
        if (index >= m_files.size())
            return Error{m_info.path + ": frame " + std::to_string(index) + " out of range (" +
                         std::to_string(m_files.size()) + " frames)"};
        auto frame = decode(index);
        if (!frame)
            return frame;
        const cv::Mat& image = frame.value().ycbcr;
        if (auto refused = refusedFrameSize((m_folder / m_files[index]).string(), image.cols,
                                            image.rows, HeaderSize{m_info.width, m_info.height}))
            return *std::move(refused);
        return frame;
    }

    /// Decodes frame `index` without comparing its size to the stream's.
    Result<Frame> decode(std::size_t index) const
    {
        const std::string path = (m_folder / m_files[index]).string();
        auto decoded = decodeImageFile(
            path, m_info.width > 0
                      ? std::optional<HeaderSize>(HeaderSize{m_info.width, m_info.height})
                      : std::nullopt);
        if (!decoded)
            return decoded.error();
        cv::Mat bgr = std::move(decoded).value();
        if (!isSaneFrameSize(bgr.cols, bgr.rows))
            return Error{path + ": absurd frame size " + std::to_string(bgr.cols) + "x" +
                         std::to_string(bgr.rows)};
        Frame frame;
        if (m_format == PixelFormat::YCbCr) {
            // The PNG's R, G, B hold Y, Cb, Cr; imread delivers them as B, G, R.
            cv::cvtColor(bgr, frame.ycbcr, cv::COLOR_BGR2RGB);
        } else {
            frame.ycbcr = bgrToYcbcr(bgr);
        }
        frame.name = m_files[index];
        const FrameMeta& meta = m_meta[index];
        frame.timestamp_ms = meta.timestamp_ms.value_or(0.0);
        frame.horizon = meta.horizon;
        return frame;
    }

    void setSize(int width, int height)
    {
        m_info.width = width;
        m_info.height = height;
    }

private:
    StreamInfo m_info;
    fs::path m_folder;
    std::vector<std::string> m_files;
    std::vector<FrameMeta> m_meta;
    PixelFormat m_format;
};

} // namespace

ReaderResult openImageFolder(const std::string& folder_arg, const std::string& spec)
{
    const fs::path folder(folder_arg);
    std::vector<std::string> files;
    std::vector<std::string> skipped;
    std::error_code ec;
    fs::directory_iterator it(folder, ec);
    if (ec)
        return Error{"cannot read " + folder_arg + ": " + ec.message()};
    for (; it != fs::directory_iterator(); it.increment(ec)) {
        if (!isImageFileName(it->path()))
            continue;
        if (auto problem = brokenFrameEntry(it->path().string()))
            skipped.push_back(std::move(*problem));
        else
            files.push_back(it->path().filename().string());
    }
    if (ec)
        return Error{"cannot read " + folder_arg + ": " + ec.message()};

    const fs::path manifest_path = folder / kManifestName;
    Manifest manifest;
    const bool has_manifest = fs::exists(manifest_path, ec);
    if (has_manifest) {
        auto parsed = parseManifest(manifest_path.string(), files.size());
        if (!parsed)
            return parsed.error();
        manifest = std::move(parsed).value();
    }
    if (files.empty()) {
        if (!has_manifest)
            if (const auto strm = findImageStrm(folder))
                return openStrm(strm->string(), spec);
        return Error{folder_arg + ": no images in the folder (.png, .jpg, .jpeg, .bmp)"};
    }
    std::sort(files.begin(), files.end(), naturalLess);

    std::vector<FrameMeta> meta(files.size());
    std::unordered_map<std::string, std::size_t> index_of;
    for (std::size_t i = 0; i < files.size(); ++i)
        index_of.emplace(files[i], i);
    for (const auto& [file, entry] : manifest.frames) {
        const auto pos = index_of.find(file);
        if (pos == index_of.end())
            return Error{manifest_path.string() + ": frame \"" + file +
                         "\" is not an image in the folder"};
        meta[pos->second] = entry;
    }

    StreamInfo info;
    info.path = spec;
    info.kind = StreamKind::ImageFolder;
    info.frame_count = files.size();
    info.fov_deg = manifest.fov_deg;
    std::sort(skipped.begin(), skipped.end(), naturalLess);
    info.warnings = reported(std::move(skipped));
    info.stream_orientation = manifest.orientation; // openStream turns the frames
    if (manifest.lut) {
        // Named by the manifest: keep it even if missing, so loading it reports the bad name.
        const fs::path lut(*manifest.lut);
        info.default_lut = (lut.is_absolute() ? lut : folder / lut).string();
    } else if (fs::is_regular_file(folder / "default.lut", ec)) {
        info.default_lut = (folder / "default.lut").string();
    }
    if (manifest.params) {
        // Kept even if missing, so loading it reports the bad name.
        const fs::path params(*manifest.params);
        info.params = (params.is_absolute() ? params : folder / params).string();
    }

    auto reader = std::make_unique<ImageFolderReader>(std::move(info), folder, std::move(files),
                                                      std::move(meta), manifest.pixel_format);
    // The first frame fixes the stream's size; decoding it now also reports a bad file early.
    auto first = reader->decode(0);
    if (!first)
        return first.error();
    reader->setSize(first.value().ycbcr.cols, first.value().ycbcr.rows);
    return std::unique_ptr<StreamReader>(std::move(reader));
}

} // namespace fieldsight::io
