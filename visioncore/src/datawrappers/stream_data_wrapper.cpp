// StreamDataWrapper: the DataWrapper the CLI and tests use, fed frame by frame from a StreamReader.
#include "visioncore/datawrappers/stream_data_wrapper.h"

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
    // Into the spare frame, so the current one survives an error; the two buffers then take
    // turns, and a steady run allocates no frame memory.
    if (Status s = m_reader->readInto(index, m_spare); !s)
        return s;
    std::swap(m_frame, m_spare);
    m_index = index;
    return {};
}

Horizon StreamDataWrapper::kinematicHorizon() const
{
    return m_frame.horizon.value_or(Horizon{});
}

} // namespace fieldsight
