#include "ui/panels/history_panel.h"

#include <QComboBox>
#include <QUndoView>
#include <QVBoxLayout>

namespace fieldsight::ui {

HistoryPanel::HistoryPanel(EditingSession& session, QWidget* parent)
    : QWidget(parent), m_session(session)
{
    setObjectName(QStringLiteral("history"));
    auto* column = new QVBoxLayout(this);
    column->setContentsMargins(0, 0, 0, 0);
    m_documents = new QComboBox(this);
    m_documents->setObjectName(QStringLiteral("history.document"));
    m_documents->setToolTip(tr("Whose edits Edit > Undo and Redo step through"));
    for (const UndoDocument& doc : session.undoDocuments())
        m_documents->addItem(doc.name);
    column->addWidget(m_documents);
    auto* view = new QUndoView(&session.undoGroup(), this);
    view->setObjectName(QStringLiteral("history.view"));
    view->setEmptyLabel(tr("<as opened>"));
    column->addWidget(view, 1);
    // The newest edit stays in sight, however long the history grows.
    connect(&session.undoGroup(), &QUndoGroup::indexChanged, view,
            [view] { view->scrollTo(view->currentIndex()); });

    connect(m_documents, &QComboBox::activated, this, [this](int i) {
        m_session.undoGroup().setActiveStack(m_session.undoDocuments()[std::size_t(i)].stack);
    });
    connect(&session.undoGroup(), &QUndoGroup::activeStackChanged, this, [this](QUndoStack* s) {
        const auto& docs = m_session.undoDocuments();
        for (std::size_t i = 0; i < docs.size(); ++i)
            if (docs[i].stack == s)
                m_documents->setCurrentIndex(int(i));
    });
}

} // namespace fieldsight::ui
