// The bookmarks document: the marked frames of the open stream, saved to the sidecar beside it at
// every change (a sidecar that could not be read is set aside, never overwritten). Adding, editing
// and removing a mark are commands on its own undo stack.
#pragma once

#include "ui/document/bookmarks.h"
#include "ui/document/disk_state.h"

#include <QObject>
#include <QString>
#include <QStringList>
#include <QUndoStack>

namespace fieldsight::ui {

class BookmarksDocument : public QObject
{
    Q_OBJECT
public:
    explicit BookmarksDocument(QObject* parent = nullptr);
    ~BookmarksDocument() override;

    /// The stream the marks belong to: its sidecar is read if there is one (an unreadable one is
    /// returned as the Error, the marks are then empty); the undo stack starts empty.
    Status setStream(const QString& spec);
    QString path() const { return m_path; }
    const Bookmarks& marks() const { return m_marks; }
    QUndoStack& undoStack() { return m_undo; }

    /// Adds or changes the mark of `frame` (named `name`, the frame's file); undoable.
    void setBookmark(std::size_t frame, const QString& name, const QString& note);
    /// Removes the mark of `frame`, if any; undoable.
    void removeBookmark(std::size_t frame);

    /// The sidecar was written (or made, or removed) by someone else since it was read or saved
    /// here; a change is then kept in memory, not written over it, until reload() or overwrite().
    bool changedOnDisk() const { return m_disk.changed(); }
    /// Reads the sidecar again (a clean reload: the marks made here since are dropped and the
    /// history starts again).
    Status reload();
    /// Writes the marks in memory over the sidecar, whatever it holds now.
    void overwrite();

signals:
    void changed();
    /// A save failed (the marks stay in memory), or the damaged sidecar was set aside.
    void problem(const QString& message);
    void notice(const QString& message);

private:
    friend class BookmarksCommand;
    void store(const Bookmarks& marks);
    void write();

    QString m_path;
    QString m_spec;
    DiskState m_disk;          ///< the sidecar as read or last saved
    bool m_unreadable = false; ///< the sidecar was refused: set aside before a save
    Bookmarks m_marks;
    QUndoStack m_undo;
};

} // namespace fieldsight::ui
