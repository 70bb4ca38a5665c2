// StrmWriter: writes version-1 NUbots image-stream records (Y duplicated into both luma bytes).
#include "visioncore/io/stream_reader.h"

#include "io/strm_format.h"
#include "io/stream_readers.h"

#include <cerrno>
#include <cstdio>
#include <cstring>

#include <unistd.h>

namespace fieldsight {

namespace {

Error writeError(const std::string& path, int error)
{
    return Error{"cannot write " + path + ": " + std::strerror(error)};
}

std::FILE* fileOf(const std::shared_ptr<void>& file)
{
    return static_cast<std::FILE*>(file.get());
}

} // namespace

Result<StrmWriter> StrmWriter::create(const std::string& path)
{
    std::FILE* file = std::fopen(path.c_str(), "wb");
    if (!file)
        return writeError(path, errno);
    StrmWriter writer(path);
    writer.m_file =
        std::shared_ptr<void>(file, [](void* f) { std::fclose(static_cast<std::FILE*>(f)); });
    return writer;
}

Status StrmWriter::append(const Frame& frame, bool flipped)
{
    if (!m_file)
        return Error{m_path + ": stream already closed"};
    const cv::Mat& image = frame.ycbcr;
    if (image.empty() || image.type() != CV_8UC3)
        return Error{m_path + ": frame \"" + frame.name + "\" is not an 8-bit 3-channel image"};
    if (!io::isSaneFrameSize(image.cols, image.rows))
        return Error{m_path + ": frame \"" + frame.name + "\" has an absurd size"};

    const cv::Mat pixels = image.isContinuous() ? image : image.clone();
    const std::size_t count = pixels.total();
    m_buffer.resize(io::kStrmHeaderSize + count * io::kStrmBytesPerPixel);
    io::StrmHeader header;
    std::memcpy(header.magic, io::kStrmMagic, 4);
    header.version = io::kStrmWriteVersion;
    header.width = pixels.cols;
    header.height = pixels.rows;
    header.timestamp_ms = frame.timestamp_ms;
    header.flipped = flipped;
    auto* raw = reinterpret_cast<unsigned char*>(m_buffer.data());
    io::encodeStrmHeader(header, raw);
    io::yCbCrToStrmPixels(pixels.data, raw + io::kStrmHeaderSize, count, flipped);
    if (std::fwrite(m_buffer.data(), 1, m_buffer.size(), fileOf(m_file)) != m_buffer.size())
        return writeError(m_path, errno);
    return {};
}

Status StrmWriter::close()
{
    if (!m_file)
        return {};
    std::FILE* file = fileOf(m_file);
    const bool flushed = std::fflush(file) == 0 && ::fsync(::fileno(file)) == 0;
    const int error = errno;
    m_file.reset(); // the deleter closes the file once no copy of this writer holds it
    if (!flushed)
        return writeError(m_path, error);
    return {};
}

} // namespace fieldsight
