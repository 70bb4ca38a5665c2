// A stream's frames turned upright as they are read (docs/formats.md, "orientation"), for every
// kind of stream, so the DataWrappers, the runs, the edit-effect scan and the LUT building all
// see the same upright frame.
#include "io/stream_readers.h"

#include <utility>

namespace fieldsight::io {

namespace {

bool isQuarterTurn(Orientation o)
{
    return o == Orientation::Clockwise90 || o == Orientation::Clockwise270;
}

class OrientedReader final : public InPlaceReader
{
public:
    OrientedReader(std::unique_ptr<StreamReader> stored, Orientation orientation)
        : m_stored(std::move(stored)), m_info(m_stored->info()), m_orientation(orientation)
    {
        m_info.orientation = orientation;
        if (isQuarterTurn(orientation))
            std::swap(m_info.width, m_info.height);
    }

    const StreamInfo& info() const override { return m_info; }
    std::string frameName(std::size_t index) const override { return m_stored->frameName(index); }

    Status readInto(std::size_t index, Frame& frame) override
    {
        // Into a buffer of its own: the turned pixels cannot be made in place.
        if (Status s = m_stored->readInto(index, m_buffer); !s)
            return s;
        orientImage(m_buffer.ycbcr, frame.ycbcr, m_orientation);
        frame.name = m_buffer.name;
        frame.timestamp_ms = m_buffer.timestamp_ms;
        // The stream's horizon describes the stored picture and turns with it.
        frame.horizon = m_buffer.horizon
                            ? orientHorizon(*m_buffer.horizon, m_orientation, m_buffer.ycbcr.rows)
                            : std::nullopt;
        return {};
    }

    Result<std::unique_ptr<StreamReader>> reopen() const override
    {
        auto stored = m_stored->reopen();
        if (!stored)
            return stored;
        return std::unique_ptr<StreamReader>(
            new OrientedReader(std::move(stored).value(), m_orientation));
    }

private:
    std::unique_ptr<StreamReader> m_stored;
    StreamInfo m_info;
    Orientation m_orientation;
    Frame m_buffer; ///< the stored frame, reused from read to read
};

} // namespace

std::unique_ptr<StreamReader> orientReader(std::unique_ptr<StreamReader> stored,
                                           Orientation orientation)
{
    return std::make_unique<OrientedReader>(std::move(stored), orientation);
}

} // namespace fieldsight::io
