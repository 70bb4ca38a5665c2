// The bookmarks document: the marked frames of the open stream, saved to the sidecar beside it at
// every change (a sidecar that could not be read is set aside, never overwritten). Adding, editing
// and removing a mark are commands on its own undo stack.
#pragma once

#include "ui/document/bookmarks.h"

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

signals:
    void changed();
    /// A save failed (the marks stay in memory), or the damaged sidecar was set aside.
    void problem(const QString& message);
    void notice(const QString& message);

private:
    friend class BookmarksCommand;
    void store(const Bookmarks& marks);

    QString m_path;
    bool m_unreadable = false; ///< the sidecar was refused: set aside before a save
    Bookmarks m_marks;
    QUndoStack m_undo;
};

} // namespace fieldsight::ui
