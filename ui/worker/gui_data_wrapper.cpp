#include "ui/worker/gui_data_wrapper.h"

namespace fieldsight::ui {

const ColourLut& GuiDataWrapper::lut() const
{
    static const ColourLut unclassified;
    return m_lut ? *m_lut : unclassified;
}

} // namespace fieldsight::ui
