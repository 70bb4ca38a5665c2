// The in-memory DataWrapper: serves a frame the host already holds (tests, the bench's cached
// frames, a GUI's current frame) with a shared, read-only LUT.
#pragma once

#include "visioncore/framework/data_wrapper.h"
#include "visioncore/io/frame.h"

#include <memory>

namespace fieldsight {

class MemoryDataWrapper : public DataWrapper
{
public:
    explicit MemoryDataWrapper(std::shared_ptr<const ColourLut> lut, cv::Mat ycbcr = {},
                               Horizon horizon = {})
        : m_lut(std::move(lut)), m_image(std::move(ycbcr)), m_horizon(horizon)
    {
    }
    /// A copy of `lut` (for tests).
    MemoryDataWrapper(cv::Mat ycbcr, ColourLut lut)
        : MemoryDataWrapper(std::make_shared<const ColourLut>(std::move(lut)), std::move(ycbcr))
    {
    }

    /// The frame to serve: the Mat's pixels are shared, not copied; the caller keeps them
    /// unchanged until the next setFrame.
    void setFrame(cv::Mat ycbcr, Horizon horizon = {})
    {
        m_image = std::move(ycbcr);
        m_horizon = horizon;
    }
    void setFrame(const Frame& frame) { setFrame(frame.ycbcr, frame.horizon.value_or(Horizon{})); }
    void setLut(std::shared_ptr<const ColourLut> lut) { m_lut = std::move(lut); }
    void setDebugSink(DebugSink* sink) { m_sink = sink; }

    const cv::Mat& image() const override { return m_image; }
    Horizon kinematicHorizon() const override { return m_horizon; }
    const ColourLut& lut() const override { return *m_lut; }
    DebugSink* debugSink() override { return m_sink; }

private:
    std::shared_ptr<const ColourLut> m_lut;
    cv::Mat m_image;
    Horizon m_horizon;
    DebugSink* m_sink = nullptr;
};

} // namespace fieldsight
