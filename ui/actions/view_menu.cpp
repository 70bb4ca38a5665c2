// View: the view mode, zoom, detection labels and the panels.
#include "ui/actions/menus.h"
#include "ui/main_window.h"

#include <QActionGroup>
#include <QMenuBar>

namespace fieldsight::ui {

void addViewMenu(MainWindow& w)
{
    FrameView& v = w.view();
    QMenu* view = w.menuBar()->addMenu(QObject::tr("&View"));
    auto* modes = new QActionGroup(&w);
    const std::pair<QString, ViewMode> mode_list[] = {
        {QObject::tr("Raw"), ViewMode::Raw},
        {QObject::tr("Classified"), ViewMode::Classified},
        {QObject::tr("Side by side"), ViewMode::SideBySide},
        {QObject::tr("Blend"), ViewMode::Blend}};
    int key = Qt::Key_1;
    for (const auto& [text, mode] : mode_list) {
        QAction* a = addMenuItem(view, text, QKeySequence(Qt::ALT | key++), &w,
                                 [&w, m = mode] { w.setMode(m); });
        a->setObjectName(QStringLiteral("view.mode.%1").arg(int(mode)));
        a->setCheckable(true);
        a->setData(int(mode));
        modes->addAction(a);
    }
    modes->actions().front()->setChecked(true);
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
    labels->setChecked(true);
    view->addSeparator();
    view->addMenu(&w.docksMenu());
}

} // namespace fieldsight::ui
