// The GUI's DataWrapper: serves the frame the worker read, with the LUT version of the request,
// to its core, and receives the debug drawings the core made for it.
#pragma once

#include "visioncore/framework/data_wrapper.h"
#include "visioncore/io/frame.h"

#include <memory>
#include <set>
#include <string>

namespace fieldsight::ui {

/// Owned by one FrameWorker and used only on its thread. Between runs the worker swaps in a new
/// frame and LUT; nothing it serves changes while the core runs.
class GuiDataWrapper : public DataWrapper, public DebugSink
{
public:
    /// The frame buffer the worker reads into (reused from frame to frame).
    Frame& frame() { return m_frame; }
    const Frame& frame() const { return m_frame; }
    void setLut(std::shared_ptr<const ColourLut> lut) { m_lut = std::move(lut); }
    void setRequestedLayers(std::set<std::string, std::less<>> layers)
    {
        m_layers = std::move(layers);
    }
    /// What the core drew for the last frame (valid until the next run).
    const DebugCanvas& canvas() const { return m_canvas ? *m_canvas : m_empty; }

    const cv::Mat& image() const override { return m_frame.ycbcr; }
    Horizon kinematicHorizon() const override { return m_frame.horizon.value_or(Horizon{}); }
    const ColourLut& lut() const override;
    DebugSink* debugSink() override { return this; }

    std::set<std::string, std::less<>> requestedLayers() const override { return m_layers; }
    void publish(const DebugCanvas& canvas) override { m_canvas = &canvas; }

private:
    Frame m_frame;
    std::shared_ptr<const ColourLut> m_lut;
    std::set<std::string, std::less<>> m_layers;
    const DebugCanvas* m_canvas = nullptr;
    DebugCanvas m_empty;
};

} // namespace fieldsight::ui
