// The bookmarks document: the marked frames of the open stream, saved to the sidecar beside it at
// every change (a sidecar that could not be read is set aside, never overwritten). Adding, editing
// and removing a mark are commands on its own undo stack.
#pragma once

#include "ui/document/bookmarks.h"
#include "ui/document/document.h"

#include <QString>

namespace fieldsight::ui {

class BookmarksDocument : public Document
{
    Q_OBJECT
public:
    explicit BookmarksDocument(QObject* parent = nullptr);

    /// The stream the marks belong to: its sidecar is read if there is one (an unreadable one is
    /// returned as the Error, the marks are then empty); the undo stack starts empty.
    Status setStream(const QString& spec);
    const Bookmarks& marks() const { return m_marks; }

    /// Adds or changes the mark of `frame` (named `name`, the frame's file); undoable.
    void setBookmark(std::size_t frame, const QString& name, const QString& note);
    /// Removes the mark of `frame`, if any; undoable.
    void removeBookmark(std::size_t frame);

    // The sidecar written (or made, or removed) by someone else since it was read or saved here
    // (changedOnDisk()): a change is then kept in memory, not written over it, until reload()
    // or overwrite().
    /// Reads the sidecar again (a clean reload: the marks made here since are dropped and the
    /// history starts again).
    Status reload();
    /// Writes the marks in memory over the sidecar, whatever it holds now.
    void overwrite();

signals:
    void changed();
    /// The damaged sidecar was set aside (a save that failed is a problem()).
    void notice(const QString& message);

private:
    friend class BookmarksCommand;
    void store(const Bookmarks& marks);
    void write();

    QString m_spec;
    Bookmarks m_marks;
};

} // namespace fieldsight::ui
