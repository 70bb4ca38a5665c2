#include "ui/tools/lut_tool_settings.h"

#include <algorithm>

namespace fieldsight::ui {

void LutToolSettings::setColour(Colour colour)
{
    if (colour == m_colour)
        return;
    m_colour = colour;
    emit changed();
}

void LutToolSettings::setTolerance(const Tolerance& t)
{
    const Tolerance clamped{std::clamp(t.y, 0, 128), std::clamp(t.cb, 0, 128),
                            std::clamp(t.cr, 0, 128)};
    if (clamped.y == m_tolerance.y && clamped.cb == m_tolerance.cb && clamped.cr == m_tolerance.cr)
        return;
    m_tolerance = clamped;
    emit changed();
}

void LutToolSettings::setBrushRadius(int radius)
{
    radius = std::clamp(radius, 0, 50);
    if (radius == m_radius)
        return;
    m_radius = radius;
    emit changed();
}

void LutToolSettings::setKeepOthers(bool on)
{
    if (on == m_keep_others)
        return;
    m_keep_others = on;
    emit changed();
}

void LutToolSettings::setSoftClasses(bool on)
{
    if (on == m_soft)
        return;
    m_soft = on;
    emit changed();
}

void LutToolSettings::setPreviewOn(bool on)
{
    if (on == m_preview)
        return;
    m_preview = on;
    emit changed();
}

} // namespace fieldsight::ui
