// Calibrate: the automatic table from the stream's frames (its button is in the LUT editor too).
#include "ui/actions/calibrate_actions.h"
#include "ui/actions/menus.h"
#include "ui/panels/lut_panel.h"

#include <QMenuBar>

namespace fieldsight::ui {

void addCalibrateMenu(QMenuBar& bar, const MenuParts& parts)
{
    QMenu* calibrate = bar.addMenu(QObject::tr("&Calibrate"));
    CalibrateActions& commands = parts.calibrate;
    QAction* automatic = addMenuItem(calibrate, QObject::tr("Automatic table"),
                                     QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_A), &commands,
                                     &CalibrateActions::automaticTable);
    automatic->setObjectName(QStringLiteral("calibrate.auto_lut"));
    automatic->setToolTip(QObject::tr(
        "Make the colour table from this stream's frames alone: the carpet, the lines, the "
        "ball and the goal found by their colours and shapes (one undo step)"));
    // Greyed while a table is made: a second click would only wait for the first.
    QObject::connect(&commands, &CalibrateActions::finished, automatic,
                     [automatic] { automatic->setEnabled(true); });
    QObject::connect(automatic, &QAction::triggered, automatic,
                     [automatic, &commands] { automatic->setEnabled(!commands.running()); });
    parts.lut_panel.addTableAction(automatic);
}

} // namespace fieldsight::ui
