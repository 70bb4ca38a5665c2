// View: the view mode, zoom, detection labels, the stream's orientation and the panels.
#include "ui/actions/menus.h"
#include "ui/document/editing_session.h"
#include "ui/frame_view/frame_view.h"

#include <QActionGroup>
#include <QDir>
#include <QMenuBar>

namespace fieldsight::ui {

namespace {

/// Which way the open stream's pictures are turned upright (an undoable edit of the stream), and
/// keeping that in its stream.json, only when asked.
void addOrientationMenu(const MenuTarget& w, QMenu& menu)
{
    StreamDocument& stream = w.session.stream();
    menu.setObjectName(QStringLiteral("view.orientation"));
    auto* turns = new QActionGroup(w.parent);
    const std::pair<QString, Orientation> turn_list[] = {
        {QObject::tr("As stored"), Orientation::Upright},
        {QObject::tr("Turn 90° clockwise"), Orientation::Clockwise90},
        {QObject::tr("Turn 180°"), Orientation::Half},
        {QObject::tr("Turn 90° anticlockwise"), Orientation::Clockwise270}};
    for (const auto& [text, o] : turn_list) {
        QAction* a = menu.addAction(text, w.parent, [w, &stream, o = o] {
            if (Status s = stream.setOrientation(o); !s) {
                w.showMessage(QString::fromStdString(s.error().message));
                return;
            }
            if (stream.orientationUnsaved() && stream.canSaveOrientation())
                w.showMessage(QObject::tr("Orientation %1° for this session; View > Orientation > "
                                          "Save to stream keeps it in the stream's stream.json.")
                                  .arg(degrees(o)),
                              false);
        });
        a->setObjectName(QStringLiteral("view.orientation.%1").arg(degrees(o)));
        a->setCheckable(true);
        turns->addAction(a);
    }
    menu.addSeparator();
    QAction* save = menu.addAction(QObject::tr("Save to stream"), w.parent, [w, &stream] {
        if (Status s = stream.saveOrientation(); !s)
            w.showMessage(QString::fromStdString(s.error().message));
        else
            w.showMessage(QObject::tr("Saved orientation %1 to %2")
                              .arg(degrees(stream.orientation()))
                              .arg(QDir(stream.streamSpec()).filePath("stream.json")),
                          false);
    });
    save->setObjectName(QStringLiteral("view.orientation.save"));
    save->setToolTip(QObject::tr("Write the orientation into the stream's stream.json"));
    // The checks follow the document (an undo turns it back too).
    const auto follow = [turns, save, &stream] {
        const int deg = degrees(stream.orientation());
        for (QAction* a : turns->actions())
            a->setChecked(a->objectName().endsWith(QLatin1Char('.') + QString::number(deg)));
        for (QAction* a : turns->actions())
            a->setEnabled(stream.hasStream() && !stream.live());
        save->setEnabled(stream.orientationUnsaved() && stream.canSaveOrientation());
    };
    QObject::connect(&stream, &StreamDocument::orientationChanged, w.parent, follow);
    QObject::connect(&stream, &StreamDocument::streamChanged, w.parent, follow);
    follow();
}

} // namespace

void addViewMenu(QMenuBar& bar, const MenuTarget& w, const MenuParts& parts)
{
    FrameView& v = parts.view;
    QMenu* view = bar.addMenu(QObject::tr("&View"));
    auto* modes = new QActionGroup(w.parent);
    const std::pair<QString, ViewMode> mode_list[] = {
        {QObject::tr("Raw"), ViewMode::Raw},
        {QObject::tr("Classified"), ViewMode::Classified},
        {QObject::tr("Side by side"), ViewMode::SideBySide},
        {QObject::tr("Blend"), ViewMode::Blend}};
    int key = Qt::Key_1;
    for (const auto& [text, mode] : mode_list) {
        QAction* a = addMenuItem(view, text, QKeySequence(Qt::ALT | key++), &v,
                                 [&v, m = mode] { v.setMode(m); });
        a->setObjectName(QStringLiteral("view.mode.%1").arg(int(mode)));
        a->setCheckable(true);
        a->setData(int(mode));
        modes->addAction(a);
    }
    modes->actions().front()->setChecked(true);
    // The checks follow the view, whoever sets its mode (the saved settings, a test).
    QObject::connect(&v, &FrameView::modeChanged, modes, [modes](ViewMode mode) {
        for (QAction* a : modes->actions())
            if (a->data().toInt() == int(mode))
                a->setChecked(true);
    });
    view->addSeparator();
    addMenuItem(view, QObject::tr("Zoom in"), QKeySequence::ZoomIn, &v, &FrameView::zoomIn);
    addMenuItem(view, QObject::tr("Zoom out"), QKeySequence::ZoomOut, &v, &FrameView::zoomOut);
    addMenuItem(view, QObject::tr("Fit to window"), QKeySequence(Qt::CTRL | Qt::Key_0), &v,
                &FrameView::fitToWindow);
    addMenuItem(view, QObject::tr("Actual pixels (100%)"), QKeySequence(Qt::CTRL | Qt::Key_1), &v,
                [&v] { v.setZoom(1); });
    QAction* labels = addMenuItem(view, QObject::tr("Detection labels"), QKeySequence(Qt::Key_T),
                                  &v, &FrameView::setLabelsShown);
    labels->setObjectName(QStringLiteral("view.labels"));
    labels->setCheckable(true);
    labels->setChecked(v.labelsShown());
    QObject::connect(&v, &FrameView::labelsShownChanged, labels, &QAction::setChecked);
    addOrientationMenu(w, *view->addMenu(QObject::tr("&Orientation")));
    // The table follows slow changes of the light over the stream (fieldsight --adapt); the
    // strip under the timeline shows how far it has moved.
    LightScan& light = w.session.lightScan();
    QAction* follow = view->addAction(QObject::tr("Follow the light"), w.parent,
                                      [&light](bool on) { light.setEnabled(on); });
    follow->setObjectName(QStringLiteral("view.follow_light"));
    follow->setCheckable(true);
    follow->setChecked(light.enabled());
    QObject::connect(&light, &LightScan::enabledChanged, follow, &QAction::setChecked);
    follow->setToolTip(QObject::tr("From the stream's table, follow slow changes of the light's "
                                   "colour and level over the frames, as --adapt does"));
    view->addSeparator();
    view->addMenu(&parts.panels);
}

} // namespace fieldsight::ui
