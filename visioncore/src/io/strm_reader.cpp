// Original NUbots image streams (.strm, design note §4.1): an index of record offsets built from
// the headers alone, and one pread per frame converted to Y, Cb, Cr in a single pass.
#include "io/sensor_strm.h"
#include "io/strm_format.h"
#include "io/stream_readers.h"
#include "visioncore/basics/atomic_file.h"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <system_error>

#include <sys/stat.h>
#include <unistd.h>

namespace fieldsight::io {

namespace {

struct StrmRecord
{
    std::uint64_t pixel_offset = 0; ///< bytes from the file start to the first pixel
    double timestamp_ms = 0;
    bool flipped = false;
};

/// Reads `size` bytes at `offset`, retrying short reads; false on error or end of file.
bool preadAll(int fd, void* buffer, std::size_t size, std::uint64_t offset)
{
    auto* out = static_cast<char*>(buffer);
    while (size > 0) {
        const ssize_t n = ::pread(fd, out, size, off_t(offset));
        if (n < 0 && errno == EINTR)
            continue;
        if (n == 0)
            errno = 0; // end of file, not an error code
        if (n <= 0)
            return false;
        out += n;
        size -= std::size_t(n);
        offset += std::uint64_t(n);
    }
    return true;
}

class StrmReader final : public InPlaceReader
{
public:
    StrmReader(StreamInfo info, int fd, std::vector<StrmRecord> records,
               std::vector<std::optional<Horizon>> horizons)
        : m_info(std::move(info)), m_fd(fd), m_records(std::move(records)),
          m_horizons(std::move(horizons))
    {
    }
    ~StrmReader() override { ::close(m_fd); }
    StrmReader(const StrmReader&) = delete;
    StrmReader& operator=(const StrmReader&) = delete;

    const StreamInfo& info() const override { return m_info; }
    std::string frameName(std::size_t index) const override { return indexedFrameName(index); }

    Status readInto(std::size_t index, Frame& frame) override
    {
        if (index >= m_records.size())
            return Error{m_info.path + ": frame " + std::to_string(index) + " out of range (" +
                         std::to_string(m_records.size()) + " frames)"};
        const StrmRecord& record = m_records[index];
        const std::size_t pixels = std::size_t(m_info.width) * std::size_t(m_info.height);
        m_buffer.resize(pixels * kStrmBytesPerPixel);
        if (!preadAll(m_fd, m_buffer.data(), m_buffer.size(), record.pixel_offset))
            return Error{m_info.path + ": cannot read record " + std::to_string(index) +
                         " at byte offset " + std::to_string(record.pixel_offset) + ": " +
                         (errno ? std::strerror(errno) : "unexpected end of file")};
        // Pixels someone else still holds are never written over: they get a buffer of their own.
        if (frame.ycbcr.u && frame.ycbcr.u->refcount > 1)
            frame.ycbcr = cv::Mat();
        frame.ycbcr.create(m_info.height, m_info.width, CV_8UC3);
        strmPixelsToYCbCr(m_buffer.data(), frame.ycbcr.data, pixels, record.flipped);
        frame.name = indexedFrameName(index);
        frame.timestamp_ms = record.timestamp_ms;
        frame.horizon = index < m_horizons.size() ? m_horizons[index] : std::nullopt;
        return {};
    }

    Result<std::unique_ptr<StreamReader>> reopen() const override
    {
        // pread keeps no file position, so a duplicate descriptor serves another thread.
        const int fd = ::dup(m_fd);
        if (fd < 0)
            return Error{m_info.path + ": cannot open again: " + std::strerror(errno)};
        return std::unique_ptr<StreamReader>(new StrmReader(m_info, fd, m_records, m_horizons));
    }

private:
    StreamInfo m_info;
    int m_fd;
    std::vector<StrmRecord> m_records;
    std::vector<std::optional<Horizon>> m_horizons;
    std::vector<std::uint8_t> m_buffer; ///< reused raw pixels of the last read record
};

} // namespace

ReaderResult openStrm(const std::string& path, const std::string& spec)
{
    // A FIFO or a device is refused, never waited on.
    auto opened = openRegularFile(path);
    if (!opened)
        return opened.error();
    // Plain names, not a structured binding: the lambdas below capture them (clang 14).
    const int fd = opened.value().fd;
    const std::uint64_t file_size = opened.value().size;
    auto fail = [&](std::size_t record, std::uint64_t offset, const std::string& problem) {
        ::close(fd);
        return Error{path + ": record " + std::to_string(record) + " at byte offset " +
                     std::to_string(offset) + ": " + problem};
    };

    StreamInfo info;
    info.path = spec;
    info.kind = StreamKind::Strm;
    std::vector<StrmRecord> records;
    std::uint64_t offset = 0;
    while (offset < file_size) {
        const std::size_t index = records.size();
        const std::uint64_t remaining = file_size - offset;
        unsigned char raw[kStrmHeaderSize];
        const std::size_t want = std::size_t(std::min<std::uint64_t>(remaining, sizeof raw));
        if (!preadAll(fd, raw, want, offset))
            return fail(index, offset,
                        std::string("cannot read header: ") +
                            (errno ? std::strerror(errno) : "unexpected end of file"));
        if (want < kStrmHeaderSizeV0)
            return fail(index, offset,
                        "truncated header (" + std::to_string(remaining) + " bytes left)");
        const StrmHeader header = decodeStrmHeader(raw);
        if (std::memcmp(header.magic, kStrmMagic, 4) != 0) {
            std::string shown;
            for (char c : header.magic)
                shown += (c >= 32 && c < 127) ? c : '?';
            return fail(index, offset, "bad magic \"" + shown + "\" (expected \"IMAG\")");
        }
        if (header.version < 0 || header.version > 1)
            return fail(index, offset,
                        "unsupported version " + std::to_string(header.version) +
                            " (this reader knows versions 0 and 1)");
        if (!std::isfinite(header.timestamp_ms))
            return fail(index, offset, "timestamp is not a finite number");
        if (!isSaneFrameSize(header.width, header.height))
            return fail(index, offset,
                        "absurd frame size " + std::to_string(header.width) + "x" +
                            std::to_string(header.height));
        if (index > 0 && (header.width != info.width || header.height != info.height))
            return fail(index, offset,
                        "frame size " + std::to_string(header.width) + "x" +
                            std::to_string(header.height) + " differs from the first record's " +
                            std::to_string(info.width) + "x" + std::to_string(info.height));
        const std::size_t header_size = strmHeaderSize(header.version);
        if (want < header_size)
            return fail(index, offset,
                        "truncated header (" + std::to_string(remaining) + " bytes left)");
        const std::uint64_t record_size = header_size + std::uint64_t(header.width) *
                                                            std::uint64_t(header.height) *
                                                            kStrmBytesPerPixel;
        if (record_size > remaining)
            return fail(index, offset,
                        "truncated record (" + std::to_string(record_size) + " bytes needed, " +
                            std::to_string(remaining) + " left)");
        if (index == 0) {
            info.width = header.width;
            info.height = header.height;
        }
        records.push_back({offset + header_size, header.timestamp_ms, header.flipped});
        offset += record_size;
    }
    if (records.empty()) {
        ::close(fd);
        return Error{path + ": empty stream (no records)"};
    }
    info.frame_count = records.size();

    namespace fs = std::filesystem;
    const fs::path folder = fs::path(path).parent_path();
    std::error_code ec;
    if (const fs::path lut = folder / "default.lut"; fs::is_regular_file(lut, ec))
        info.default_lut = lut.string();

    // The horizon is optional: a missing or unreadable sensor.strm leaves the frames without one.
    std::vector<std::optional<Horizon>> horizons;
    if (const auto sensors = findSensorStrmFor(path)) {
        auto parsed = readSensorHorizons(*sensors, info.width, records.size());
        if (parsed)
            horizons = std::move(parsed).value();
    }
    return std::unique_ptr<StreamReader>(
        new StrmReader(std::move(info), fd, std::move(records), std::move(horizons)));
}

} // namespace fieldsight::io
