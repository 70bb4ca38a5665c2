// The history dock: the undo history of the active document (the one edited last, or chosen
// here), where clicking a step undoes or redoes to it.
#pragma once

#include "ui/document/editing_session.h"

#include <QWidget>

class QComboBox;

namespace fieldsight::ui {

class HistoryPanel : public QWidget
{
    Q_OBJECT
public:
    explicit HistoryPanel(EditingSession& session, QWidget* parent = nullptr);

private:
    EditingSession& m_session;
    QComboBox* m_documents = nullptr;
};

} // namespace fieldsight::ui
