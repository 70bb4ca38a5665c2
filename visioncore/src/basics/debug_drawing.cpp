// Debug layers that exist only when requested.
#include "visioncore/basics/debug_drawing.h"

namespace fieldsight {

DebugDrawing* DebugCanvas::layer(std::string_view id)
{
    if (m_requested.empty() || !wants(id))
        return nullptr;
    auto it = m_drawings.find(id);
    if (it == m_drawings.end())
        it = m_drawings.emplace(std::string(id), DebugDrawing{std::string(id), {}, {}}).first;
    return &it->second;
}

} // namespace fieldsight
