// What the LUT tools share: the class they paint, the tolerance box, the brush size, and whether
// edits keep other classes' cells or make soft classes where two meet. The LUT editor dock shows
// and changes them; the tools read them.
#pragma once

#include "visioncore/basics/colour.h"
#include "visioncore/services/lut_editing.h"

#include <QObject>

namespace fieldsight::ui {

class LutToolSettings : public QObject
{
    Q_OBJECT
public:
    using QObject::QObject;

    Colour colour() const { return m_colour; }
    void setColour(Colour colour);
    Tolerance tolerance() const { return m_tolerance; }
    void setTolerance(const Tolerance& tolerance);
    /// Image px (a dab of radius 0 is one pixel); in the UV plane, cells.
    int brushRadius() const { return m_radius; }
    void setBrushRadius(int radius);
    /// Edits leave cells of other classes alone.
    bool keepOthers() const { return m_keep_others; }
    void setKeepOthers(bool on);
    /// Where pink or yellow meets orange, edits make the soft class (pink_orange, yellow_orange).
    bool softClasses() const { return m_soft; }
    void setSoftClasses(bool on);
    /// The tools show what they would change under the cursor.
    bool previewOn() const { return m_preview; }
    void setPreviewOn(bool on);

signals:
    void changed();

private:
    Colour m_colour = Colour::Orange;
    Tolerance m_tolerance{8, 4, 4};
    int m_radius = 2;
    bool m_keep_others = false;
    bool m_soft = false;
    bool m_preview = true;
};

} // namespace fieldsight::ui
