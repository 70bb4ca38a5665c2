#include "ui/widgets/message_bar.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QTimer>
#include <QToolButton>

namespace fieldsight::ui {

namespace {

void setColours(QWidget* widget, QColor window)
{
    QPalette pal = widget->palette();
    pal.setColor(QPalette::Window, window);
    pal.setColor(QPalette::WindowText, QColor(20, 20, 20));
    widget->setPalette(pal);
}

} // namespace

MessageBar::MessageBar(QWidget* parent) : QWidget(parent)
{
    setObjectName(QStringLiteral("message_bar"));
    setAutoFillBackground(true);
    auto* row = new QHBoxLayout(this);
    row->setContentsMargins(8, 4, 4, 4);
    m_text = new QLabel(this);
    m_text->setWordWrap(true);
    m_text->setTextInteractionFlags(Qt::TextSelectableByMouse);
    row->addWidget(m_text, 1);
    auto* close = new QToolButton(this);
    close->setText(QStringLiteral("✕"));
    close->setAutoRaise(true);
    close->setToolTip(tr("Close"));
    connect(close, &QToolButton::clicked, this, &QWidget::hide);
    row->addWidget(close);
    m_fade = new QTimer(this);
    m_fade->setSingleShot(true);
    m_fade->setInterval(kInfoShownMs);
    connect(m_fade, &QTimer::timeout, this, [this] {
        if (underMouse())
            m_fade->start(); // being read or copied
        else
            hide();
    });
    hide();
}

void MessageBar::show(const QString& text, bool error)
{
    setColours(this, error ? QColor(255, 222, 222) : QColor(222, 240, 255));
    m_text->setPalette(palette());
    m_text->setText(text);
    QWidget::show();
    if (error)
        m_fade->stop();
    else
        m_fade->start();
}

QString MessageBar::text() const
{
    return m_text->text();
}

OfferBar::OfferBar(const QString& accept, const QString& decline, QWidget* parent) : QWidget(parent)
{
    setAutoFillBackground(true);
    setColours(this, QColor(255, 244, 200));
    auto* row = new QHBoxLayout(this);
    row->setContentsMargins(8, 4, 4, 4);
    m_text = new QLabel(this);
    m_text->setTextFormat(Qt::PlainText);
    m_text->setWordWrap(true);
    // A long unbreakable word (a path) must not widen the bar past the window.
    m_text->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    m_text->setMinimumWidth(0);
    row->addWidget(m_text, 1);
    auto* yes = new QPushButton(accept, this);
    yes->setObjectName(QStringLiteral("accept"));
    connect(yes, &QPushButton::clicked, this, [this] {
        hide();
        emit accepted();
    });
    row->addWidget(yes);
    auto* no = new QPushButton(decline, this);
    no->setObjectName(QStringLiteral("decline"));
    connect(no, &QPushButton::clicked, this, [this] {
        hide();
        emit declined();
    });
    row->addWidget(no);
    hide();
}

QString OfferBar::question() const
{
    return m_text->text();
}

void OfferBar::offer(const QString& question, const QString& details)
{
    m_text->setText(question);
    m_text->setToolTip(details);
    show();
}

} // namespace fieldsight::ui
