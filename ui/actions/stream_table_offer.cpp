// After Save LUT As: the offer to make the table the stream's own, with the orientation it was
// made on (a table made on upright frames is no use to `run` reading them upside down).
#include "ui/actions/session_files.h"
#include "ui/adapters/local_path.h"
#include "ui/dialogs/dialogs.h"
#include "ui/document/editing_session.h"
#include "visioncore/io/orientation.h"

#include <QFileInfo>

namespace fieldsight::ui {

void SessionFiles::offerAsStreamTable(const QString& path)
{
    // A table saved under another name is not what the stream opens with next time, unless
    // its manifest names it: offer that.
    StreamDocument& stream = m_target.session.stream();
    if (!stream.hasStream() || !QFileInfo(stream.streamSpec()).isDir())
        return;
    const QString own = fromLocalPath(stream.info().default_lut);
    if (!own.isEmpty() && QFileInfo(own).absoluteFilePath() == QFileInfo(path).absoluteFilePath())
        return;
    const QString text =
        tr("Use %1 as the table of the stream %2? Its stream.json then names it, and the stream "
           "opens with it next time (in the window and on the command line).")
            .arg(QFileInfo(path).fileName(), stream.streamSpec());
    const QString title = tr("Use as this stream's table");
    // The table was made on the frames as shown: when they are turned and the manifest does not
    // say so, the commands would read them the other way round. Ask about that too.
    const bool turned = stream.orientationUnsaved() && stream.canSaveOrientation();
    bool with_orientation = false;
    if (turned) {
        const int deg = degrees(stream.orientation());
        const int choice = Dialogs::current().choice(
            m_target.parent, title,
            text + QStringLiteral("\n\n") +
                tr("The frames are shown turned %1°, which its stream.json does not say. Save "
                   "the orientation with the table, so fieldsight run reads the frames as the "
                   "table was made on them?")
                    .arg(deg),
            {tr("Table and orientation %1°").arg(deg), tr("Table only")}, 0);
        if (choice < 0) // Cancel: neither
            return;
        with_orientation = choice == 0;
    } else if (Dialogs::current().question(m_target.parent, title, text,
                                           QMessageBox::Yes | QMessageBox::No,
                                           QMessageBox::Yes) != QMessageBox::Yes) {
        return;
    }
    if (Status s = writeStreamLut(toLocalPath(streamFolder()), toLocalPath(path)); !s) {
        m_target.showMessage(QString::fromStdString(s.error().message));
        return;
    }
    stream.manifestWritten(); // the window's own write: no other writer's change
    if (with_orientation) {
        if (Status s = stream.saveOrientation(); !s) {
            m_target.showMessage(tr("Saved %1 as the stream's table, but not its orientation: %2")
                                     .arg(path, QString::fromStdString(s.error().message)));
            return;
        }
        m_target.showMessage(tr("Saved %1; the stream %2 now opens with it, turned %3°")
                                 .arg(path, stream.streamSpec())
                                 .arg(degrees(stream.orientation())),
                             false);
        return;
    }
    m_target.showMessage(
        tr("Saved %1; the stream %2 now opens with it").arg(path, stream.streamSpec()), false);
}

} // namespace fieldsight::ui
