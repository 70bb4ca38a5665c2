// The file-stream DataWrapper: serves frames of a StreamReader with a LUT to the core, upright
// (the reader turns them by the stream's orientation, or the one it was opened with).
#pragma once

#include "visioncore/framework/data_wrapper.h"
#include "visioncore/io/frame.h"
#include "visioncore/io/stream_reader.h"

#include <memory>

namespace fieldsight {

class StreamDataWrapper : public DataWrapper
{
public:
    /// `lut` is shared read-only (every worker of a run serves the same table).
    StreamDataWrapper(std::unique_ptr<StreamReader> reader, std::shared_ptr<const ColourLut> lut);
    StreamDataWrapper(std::unique_ptr<StreamReader> reader, ColourLut lut)
        : StreamDataWrapper(std::move(reader), std::make_shared<const ColourLut>(std::move(lut)))
    {
    }

    /// Makes frame `index` current. On error the previous frame stays current.
    Status seek(std::size_t index);
    const Frame& frame() const { return m_frame; }
    std::size_t frameIndex() const { return m_index; }
    StreamReader& reader() { return *m_reader; }
    /// How far the stored pictures are turned before the core sees them.
    Orientation orientation() const { return m_reader->info().orientation; }
    void setLut(std::shared_ptr<const ColourLut> lut) { m_lut = std::move(lut); }
    void setDebugSink(DebugSink* sink) { m_sink = sink; }

    const cv::Mat& image() const override { return m_frame.ycbcr; }
    Horizon kinematicHorizon() const override;
    const ColourLut& lut() const override { return *m_lut; }
    DebugSink* debugSink() override { return m_sink; }

private:
    std::unique_ptr<StreamReader> m_reader;
    std::shared_ptr<const ColourLut> m_lut;
    Frame m_frame;
    Frame m_spare; ///< the frame before, reused by the next seek
    std::size_t m_index = 0;
    DebugSink* m_sink = nullptr;
};

} // namespace fieldsight
