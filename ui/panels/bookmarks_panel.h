// The bookmarks dock: the stream's marked frames with their notes (activate one to go there),
// marking the current frame with a note, and removing a mark; every change an undoable command
// of the bookmarks document.
#pragma once

#include "ui/document/bookmarks_document.h"
#include "ui/document/stream_document.h"

#include <QWidget>

class QListWidget;

namespace fieldsight::ui {

class BookmarksPanel : public QWidget
{
    Q_OBJECT
public:
    BookmarksPanel(BookmarksDocument& marks, StreamDocument& stream, QWidget* parent = nullptr);

    QListWidget& list() { return *m_list; }
    /// Asks for a note and marks the current frame (or edits its mark).
    void markCurrentFrame();
    /// Goes to the next mark after the current frame (direction > 0) or the one before.
    void jump(int direction);

private:
    void refresh();

    BookmarksDocument& m_marks;
    StreamDocument& m_stream;
    QListWidget* m_list = nullptr;
};

} // namespace fieldsight::ui
