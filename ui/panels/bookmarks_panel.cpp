#include "ui/panels/bookmarks_panel.h"

#include "ui/dialogs/dialogs.h"

#include <QHBoxLayout>
#include <QListWidget>
#include <QPushButton>
#include <QVBoxLayout>

namespace fieldsight::ui {

BookmarksPanel::BookmarksPanel(BookmarksDocument& marks, StreamDocument& stream, QWidget* parent)
    : QWidget(parent), m_marks(marks), m_stream(stream)
{
    auto* column = new QVBoxLayout(this);
    column->setContentsMargins(0, 0, 0, 0);
    m_list = new QListWidget(this);
    m_list->setObjectName(QStringLiteral("bookmarks"));
    connect(m_list, &QListWidget::itemActivated, this, [this](QListWidgetItem* item) {
        m_stream.setCurrentIndex(std::size_t(item->data(Qt::UserRole).toULongLong()));
    });
    column->addWidget(m_list, 1);
    auto* row = new QHBoxLayout;
    auto* add = new QPushButton(tr("Mark frame…"), this);
    connect(add, &QPushButton::clicked, this, &BookmarksPanel::markCurrentFrame);
    auto* remove = new QPushButton(tr("Remove"), this);
    remove->setObjectName(QStringLiteral("bookmarks.remove"));
    connect(remove, &QPushButton::clicked, this, [this] {
        if (QListWidgetItem* item = m_list->currentItem())
            m_marks.removeBookmark(std::size_t(item->data(Qt::UserRole).toULongLong()));
    });
    row->addWidget(add);
    row->addWidget(remove);
    column->addLayout(row);
    connect(&m_marks, &BookmarksDocument::changed, this, &BookmarksPanel::refresh);
    refresh();
}

void BookmarksPanel::markCurrentFrame()
{
    if (!m_stream.hasStream())
        return;
    const std::size_t frame = m_stream.currentIndex();
    const Bookmark* existing = m_marks.marks().find(frame);
    const auto note =
        Dialogs::current().text(this, tr("Bookmark frame %1").arg(frame), tr("Note:"),
                                existing ? QString::fromStdString(existing->note) : QString());
    if (note)
        m_marks.setBookmark(frame, m_stream.frameName(frame), *note);
}

void BookmarksPanel::jump(int direction)
{
    const auto& list = m_marks.marks().list();
    const std::size_t now = m_stream.currentIndex();
    if (direction > 0) {
        for (const Bookmark& b : list)
            if (b.frame > now)
                return m_stream.setCurrentIndex(b.frame);
    } else {
        for (auto it = list.rbegin(); it != list.rend(); ++it)
            if (it->frame < now)
                return m_stream.setCurrentIndex(it->frame);
    }
}

void BookmarksPanel::refresh()
{
    m_list->clear();
    for (const Bookmark& b : m_marks.marks().list()) {
        auto* item =
            new QListWidgetItem(tr("%1  %2")
                                    .arg(qulonglong(b.frame), 6)
                                    .arg(QString::fromStdString(b.note.empty() ? b.name : b.note)),
                                m_list);
        item->setData(Qt::UserRole, qulonglong(b.frame));
        item->setToolTip(QString::fromStdString(b.name));
    }
}

} // namespace fieldsight::ui
