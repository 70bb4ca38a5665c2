#include "ui/document/bookmarks_document.h"

#include "ui/adapters/local_path.h"

#include <QUndoCommand>

namespace fieldsight::ui {

/// A change of the marks: the list before and after (marks are few and small).
class BookmarksCommand : public QUndoCommand
{
public:
    BookmarksCommand(BookmarksDocument& doc, const QString& text, Bookmarks before, Bookmarks after)
        : QUndoCommand(text), m_doc(doc), m_before(std::move(before)), m_after(std::move(after))
    {
    }
    void redo() override { m_doc.store(m_after); }
    void undo() override { m_doc.store(m_before); }

private:
    BookmarksDocument& m_doc;
    Bookmarks m_before;
    Bookmarks m_after;
};

BookmarksDocument::BookmarksDocument(QObject* parent) : Document(Saving::EveryChange, parent) {}

Status BookmarksDocument::setStream(const QString& spec)
{
    clearHistory();
    m_marks = Bookmarks{};
    setUnreadable(false);
    m_spec = spec;
    setFile(fromLocalPath(Bookmarks::sidecarPath(toLocalPath(spec))));
    Status status;
    if (!path().isEmpty()) {
        auto marks = Bookmarks::load(toLocalPath(path()));
        if (marks) {
            m_marks = std::move(marks).value();
        } else {
            setUnreadable(true);
            status = Error{marks.error().message +
                           " (it is set aside, not overwritten, when a bookmark is saved)"};
        }
    }
    emit changed();
    return status;
}

void BookmarksDocument::setBookmark(std::size_t frame, const QString& name, const QString& note)
{
    Bookmarks after = m_marks;
    const Bookmark* existing = m_marks.find(frame);
    after.set({frame, toLocalPath(name), note.toStdString()});
    undoStack().push(new BookmarksCommand(*this,
                                          existing ? tr("Edit bookmark of frame %1").arg(frame)
                                                   : tr("Bookmark frame %1").arg(frame),
                                          m_marks, std::move(after)));
}

void BookmarksDocument::removeBookmark(std::size_t frame)
{
    Bookmarks after = m_marks;
    if (!after.remove(frame))
        return;
    undoStack().push(new BookmarksCommand(*this, tr("Remove bookmark of frame %1").arg(frame),
                                          m_marks, std::move(after)));
}

Status BookmarksDocument::reload()
{
    return setStream(m_spec);
}

void BookmarksDocument::overwrite()
{
    if (!path().isEmpty())
        write();
}

void BookmarksDocument::store(const Bookmarks& marks)
{
    m_marks = marks;
    emit changed();
    if (path().isEmpty()) {
        emit problem(tr("a live camera has no file to keep bookmarks beside (the bookmarks are "
                        "kept until the window closes)"));
        return;
    }
    if (changedOnDisk()) {
        emit problem(tr("%1 changed on disk since this window read it (another window or a "
                        "program wrote it): the bookmarks are kept here, not written over it; "
                        "reload it or keep yours")
                         .arg(path()));
        return;
    }
    write();
}

void BookmarksDocument::write()
{
    auto saved = writeAtChange([this](const std::string& file) { return m_marks.save(file); });
    if (!saved)
        emit problem(QString::fromStdString(saved.error().message) +
                     tr(" (the bookmarks are kept until the window closes)"));
    else if (!saved.value().empty())
        emit notice(QString::fromStdString(saved.value()));
}

} // namespace fieldsight::ui
