// StreamDataWrapper: the DataWrapper the CLI and tests use, fed frame by frame from a StreamReader.
#include "visioncore/io/stream_data_wrapper.h"

namespace fieldsight {

StreamDataWrapper::StreamDataWrapper(std::unique_ptr<StreamReader> reader,
                                     std::shared_ptr<const ColourLut> lut)
    : m_reader(std::move(reader)), m_lut(std::move(lut))
{
}

Status StreamDataWrapper::seek(std::size_t index)
{
    const StreamInfo& info = m_reader->info();
    // A camera (frame_count 0) has no end; its reader returns the next live frame.
    if (info.kind != StreamKind::Camera && index >= info.frame_count)
        return Error{info.path + ": frame " + std::to_string(index) + " out of range (" +
                     std::to_string(info.frame_count) + " frames)"};
    auto frame = m_reader->read(index);
    if (!frame)
        return frame.error();
    m_frame = std::move(frame).value();
    m_index = index;
    return {};
}

Horizon StreamDataWrapper::kinematicHorizon() const
{
    return m_frame.horizon.value_or(Horizon{});
}

} // namespace fieldsight
