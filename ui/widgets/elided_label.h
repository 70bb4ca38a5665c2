// A one-line label that shows as much of its text as fits and ends it with "…" where it is cut,
// so a reader sees there is more; text() keeps the whole line (give it as the tooltip too).
#pragma once

#include <QLabel>

namespace fieldsight::ui {

class ElidedLabel : public QLabel
{
    Q_OBJECT

public:
    explicit ElidedLabel(QWidget* parent = nullptr);

    /// The line as it is drawn at the label's width: the whole text, or its start and "…".
    QString shownText() const;

protected:
    void paintEvent(QPaintEvent* event) override;
};

} // namespace fieldsight::ui
