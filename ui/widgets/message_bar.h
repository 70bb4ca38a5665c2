// The bar above the frame where the window says what went wrong (red) or what it did (blue). A
// problem stays until closed or replaced; a report of what was done goes after kInfoShownMs (not
// while the mouse is on it), as it floats over the frame's top. Its text can be selected and
// copied, and the status bar and History keep it.
#pragma once

#include <QWidget>

class QLabel;
class QPushButton;
class QTimer;

namespace fieldsight::ui {

class MessageBar : public QWidget
{
    Q_OBJECT
public:
    static constexpr int kInfoShownMs = 8000;

    explicit MessageBar(QWidget* parent = nullptr);
    void show(const QString& text, bool error);
    QString text() const;

private:
    QLabel* m_text = nullptr;
    QTimer* m_fade = nullptr; ///< hides a report of what was done
};

/// The bar offering what a session that ended without saving left (unsaved edits): a question
/// and two answers. The question is plain text (never read as HTML), wraps, and gives way to the
/// buttons: they stay in the bar however long it is.
class OfferBar : public QWidget
{
    Q_OBJECT
public:
    OfferBar(const QString& accept, const QString& decline, QWidget* parent = nullptr);
    /// Shows `question`, with `details` (the full paths the question shortens) as its tooltip.
    void offer(const QString& question, const QString& details = {});
    QString question() const;

signals:
    void accepted();
    void declined();

private:
    QLabel* m_text = nullptr;
};

} // namespace fieldsight::ui
