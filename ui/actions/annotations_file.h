// What the window does with the annotations document's file: Save Annotations (Save As for a
// stream without a file, or whose file could not be read), asking before unsaved annotation edits
// are dropped (another stream, closing), and offering a crashed session's annotation edits back
// when their own stream opens. Every question goes through the Dialogs seam and every error to the
// window's message bar.
#pragma once

#include "ui/actions/menus.h"

#include <QObject>
#include <QString>

namespace fieldsight::ui {

class AnnotationsDocument;
class OfferBar;

class AnnotationsFile : public QObject
{
    Q_OBJECT
public:
    /// Offers a crashed session's edits in `recovery_bar`.
    AnnotationsFile(const MenuTarget& target, OfferBar& recovery_bar);

    /// Saves the annotations to their file, atomically; asks for another file (Save As) when
    /// they have none or theirs could not be read, and what to do when another window or
    /// program changed it since (reload, Save As, overwrite, cancel). False with a message when
    /// edits are left unsaved.
    bool save();
    /// Reads the annotations file again as one undo step (the edits before it are dropped,
    /// Undo brings them back); false with a message when it cannot be read.
    bool reload();
    /// Saves them to `path` (asks for one when empty); the file becomes theirs.
    bool saveAs(const QString& path = {});
    /// Asks what to do with unsaved annotation edits (save, discard, cancel); true to go on.
    /// Discarded edits are reverted to the file (and their recovery file removed).
    bool confirmChanges();

    /// Shows the offer of a recovery file left for the open stream, if any (hides it otherwise).
    void offerRecovery();
    /// Loads the offered recovery onto the open stream's annotations (only its own stream's).
    bool recover();
    void discardRecovery();

private:
    AnnotationsDocument& doc();
    /// Back to the annotations as saved: the file read again (empty when it is absent).
    void revert();

    MenuTarget m_target;
    OfferBar& m_recovery_bar;
};

} // namespace fieldsight::ui
