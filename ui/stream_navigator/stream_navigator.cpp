#include "ui/stream_navigator/stream_navigator.h"

#include "ui/dialogs/dialogs.h"

#include <QAction>
#include <QComboBox>
#include <QHBoxLayout>
#include <QVBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QSlider>
#include <QStyle>
#include <QToolButton>

namespace fieldsight::ui {

StreamNavigator::StreamNavigator(StreamDocument& document, QWidget* parent)
    : QWidget(parent), m_doc(document)
{
    setObjectName(QStringLiteral("navigator"));
    auto* rows = new QVBoxLayout(this);
    rows->setContentsMargins(4, 2, 4, 2);
    rows->setSpacing(0);
    auto* row = new QHBoxLayout;
    auto button = [&](QAction* a) {
        auto* b = new QToolButton(this);
        b->setDefaultAction(a);
        b->setAutoRaise(true);
        row->addWidget(b);
    };
    auto* st = style();
    QAction* first = makeAction(
        tr("First frame"), Qt::Key_Home, [this] { goToFrame(0); }, "first");
    first->setIcon(st->standardIcon(QStyle::SP_MediaSkipBackward));
    QAction* back100 = makeAction(
        tr("Back 100 frames"), Qt::CTRL | Qt::Key_Left, [this] { step(-100); }, "back100");
    QAction* back10 = makeAction(
        tr("Back 10 frames"), Qt::SHIFT | Qt::Key_Left, [this] { step(-10); }, "back10");
    QAction* prev = makeAction(
        tr("Previous frame"), Qt::Key_Left, [this] { step(-1); }, "prev");
    prev->setIcon(st->standardIcon(QStyle::SP_MediaSeekBackward));
    m_play = makeAction(
        tr("Play"), Qt::Key_Space, [this] { setPlaying(!playing()); }, "play");
    m_play->setIcon(st->standardIcon(QStyle::SP_MediaPlay));
    QAction* next = makeAction(
        tr("Next frame"), Qt::Key_Right, [this] { step(1); }, "next");
    next->setIcon(st->standardIcon(QStyle::SP_MediaSeekForward));
    QAction* fwd10 = makeAction(
        tr("Forward 10 frames"), Qt::SHIFT | Qt::Key_Right, [this] { step(10); }, "fwd10");
    QAction* fwd100 = makeAction(
        tr("Forward 100 frames"), Qt::CTRL | Qt::Key_Right, [this] { step(100); }, "fwd100");
    QAction* last = makeAction(
        tr("Last frame"), Qt::Key_End,
        [this] { goToFrame(m_doc.frameCount() ? m_doc.frameCount() - 1 : 0); }, "last");
    last->setIcon(st->standardIcon(QStyle::SP_MediaSkipForward));
    back100->setIconText(QStringLiteral("−100"));
    back10->setIconText(QStringLiteral("−10"));
    fwd10->setIconText(QStringLiteral("+10"));
    fwd100->setIconText(QStringLiteral("+100"));
    auto* sep = new QAction(this);
    sep->setSeparator(true);
    m_actions << sep;
    makeAction(
        tr("Go to frame…"), Qt::CTRL | Qt::Key_G, [this] { askGoTo(); }, "goto");
    m_loop = makeAction(
        tr("Loop"), Qt::Key_L, [] {}, "loop");
    m_loop->setCheckable(true);

    for (QAction* a : {first, back10, prev, m_play, next, fwd10, last}) // ±100: keys and menu
        button(a);

    m_slider = new QSlider(Qt::Horizontal, this);
    m_slider->setObjectName(QStringLiteral("frame_slider"));
    m_slider->setPageStep(10);
    m_slider->setFocusPolicy(Qt::NoFocus); // the arrow keys are the window's frame steps
    connect(m_slider, &QSlider::valueChanged, this,
            [this](int v) { goToFrame(std::size_t(std::max(0, v))); });
    rows->addWidget(m_slider); // the whole width: one frame is as many pixels as can be
    rows->addLayout(row);

    m_label = new QLabel(this);
    m_label->setObjectName(QStringLiteral("frame_label"));
    m_label->setMinimumWidth(200);
    m_label->setTextInteractionFlags(Qt::TextSelectableByMouse);

    m_speed_box = new QComboBox(this);
    m_speed_box->setToolTip(tr("Play speed"));
    for (int fps : {1, 5, 10, 15, 30, 60})
        m_speed_box->addItem(tr("%1 fps").arg(fps), fps);
    m_speed_box->addItem(tr("fastest"), 0);
    m_speed_box->setFocusPolicy(Qt::NoFocus);
    connect(m_speed_box, &QComboBox::activated, this,
            [this](int i) { setSpeed(m_speed_box->itemData(i).toInt()); });
    row->addWidget(m_speed_box);
    auto* loop = new QToolButton(this);
    loop->setDefaultAction(m_loop);
    row->addWidget(loop);
    row->addSpacing(8);
    row->addWidget(m_label, 1);

    m_timer.setTimerType(Qt::PreciseTimer);
    connect(&m_timer, &QTimer::timeout, this, &StreamNavigator::tick);
    connect(&m_doc, &StreamDocument::streamChanged, this, &StreamNavigator::refresh);
    connect(&m_doc, &StreamDocument::currentIndexChanged, this, &StreamNavigator::refresh);
    connect(&m_doc, &StreamDocument::frameReady, this, [this] {
        showFrameInfo();
        if (m_playing && m_fps == 0)
            QTimer::singleShot(0, this, &StreamNavigator::tick); // after the frame is painted
    });
    setSpeed(m_fps);
    refresh();
}

QAction* StreamNavigator::makeAction(const QString& text, const QKeySequence& key,
                                     std::function<void()> run, const QString& name)
{
    auto* a = new QAction(text, this);
    a->setObjectName(name);
    a->setShortcut(key);
    a->setToolTip(QStringLiteral("%1 (%2)").arg(text, key.toString(QKeySequence::NativeText)));
    connect(a, &QAction::triggered, this, std::move(run));
    m_actions << a;
    return a;
}

void StreamNavigator::addTimelineStrip(QWidget* strip)
{
    auto* rows = static_cast<QVBoxLayout*>(layout());
    rows->insertWidget(rows->indexOf(m_slider), strip);
}

void StreamNavigator::step(long long delta)
{
    if (!m_doc.hasStream())
        return;
    long long target = (long long)(m_doc.currentIndex()) + delta;
    const long long count = (long long)(m_doc.frameCount());
    if (!m_doc.live())
        target = std::clamp(target, 0LL, std::max(0LL, count - 1));
    goToFrame(std::size_t(std::max(0LL, target)));
}

void StreamNavigator::goToFrame(std::size_t index)
{
    m_doc.setCurrentIndex(index);
}

void StreamNavigator::askGoTo()
{
    if (!m_doc.hasStream() || m_doc.live())
        return;
    const int count = int(m_doc.frameCount());
    if (const auto frame = Dialogs::current().number(this, tr("Go to frame"),
                                                     tr("Frame index (0 to %1):").arg(count - 1),
                                                     int(m_doc.currentIndex()), 0, count - 1))
        goToFrame(std::size_t(*frame));
}

void StreamNavigator::setPlaying(bool on)
{
    if (on == playing())
        return;
    if (on && m_doc.frameCount() > 0 && !m_doc.live() &&
        m_doc.currentIndex() + 1 >= m_doc.frameCount())
        goToFrame(0); // play from the start again
    m_playing = on;
    if (on) {
        if (m_fps > 0)
            m_timer.start(1000 / m_fps);
        m_fps_clock.start();
        m_fps_frames = 0;
        if (m_fps == 0)
            tick();
    } else {
        m_timer.stop();
        m_measured_fps = 0;
    }
    m_play->setText(on ? tr("Pause") : tr("Play"));
    m_play->setIcon(style()->standardIcon(on ? QStyle::SP_MediaPause : QStyle::SP_MediaPlay));
    emit playingChanged(on);
    showFrameInfo();
}

void StreamNavigator::setSpeed(int fps)
{
    m_fps = std::max(0, fps);
    m_speed_box->setCurrentIndex(std::max(0, m_speed_box->findData(m_fps)));
    if (playing() && m_fps > 0)
        m_timer.start(1000 / m_fps);
    else
        m_timer.stop();
    if (playing() && m_fps == 0)
        tick();
}

void StreamNavigator::tick()
{
    if (!m_playing)
        return;
    if (m_doc.waiting())
        return; // the frame before is not done: skip this tick rather than queue
    const std::size_t next = m_doc.currentIndex() + 1;
    if (!m_doc.live() && next >= m_doc.frameCount()) {
        if (m_loop->isChecked())
            goToFrame(0);
        else
            setPlaying(false);
    } else {
        goToFrame(next);
    }
    ++m_fps_frames;
    if (m_fps_clock.elapsed() >= 1000) {
        m_measured_fps = m_fps_frames * 1000.0 / double(m_fps_clock.restart());
        m_fps_frames = 0;
    }
}

void StreamNavigator::refresh()
{
    const bool open = m_doc.hasStream();
    const bool seekable = open && !m_doc.live();
    // A live camera cannot seek; its next frame is the newest one the camera has.
    for (QAction* a : m_actions)
        if (a != m_play && a != m_loop)
            a->setEnabled(seekable || (open && a->objectName() == QLatin1String("next")));
    m_play->setEnabled(open);
    {
        QSignalBlocker block(m_slider);
        m_slider->setEnabled(seekable);
        m_slider->setRange(0, seekable ? int(m_doc.frameCount()) - 1 : 0);
        m_slider->setValue(int(m_doc.currentIndex()));
    }
    showFrameInfo();
}

void StreamNavigator::showFrameInfo()
{
    if (!m_doc.hasStream()) {
        m_label->setText(tr("no stream"));
        return;
    }
    const std::size_t i = m_doc.currentIndex();
    QString text = m_doc.live() ? tr("%1 (live)").arg(i)
                                : tr("%1 / %2").arg(i).arg(qsizetype(m_doc.frameCount()) - 1);
    const auto& out = m_doc.current();
    if (out && out->index == i) {
        text += QStringLiteral("  ·  ") + QString::fromStdString(out->frame.name);
        text += QStringLiteral("  ·  %1 ms").arg(out->frame.timestamp_ms, 0, 'f', 1);
    } else {
        text += QStringLiteral("  ·  ") + m_doc.frameName(i);
    }
    if (playing() && m_measured_fps > 0)
        text += tr("  ·  %1 fps").arg(m_measured_fps, 0, 'f', 1);
    m_label->setText(text);
}

} // namespace fieldsight::ui
