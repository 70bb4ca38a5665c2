#include "ui/main_window.h"

#include "ui/actions/annotations_file.h"
#include "ui/actions/calibrate_actions.h"
#include "ui/actions/fit_actions.h"
#include "ui/actions/disk_watch.h"
#include "ui/actions/session_files.h"
#include "ui/actions/menus.h"
#include "ui/frame_view/cell_highlights.h"
#include "ui/recording/frame_recorder.h"
#include "ui/panels/bookmarks_panel.h"
#include "ui/panels/detections_panel.h"
#include "ui/panels/evaluation_panel.h"
#include "ui/panels/history_panel.h"
#include "ui/panels/inspector_panel.h"
#include "ui/panels/layers_panel.h"
#include "ui/panels/lut_panel.h"
#include "ui/panels/pipeline_panel.h"
#include "ui/panels/uv_plane_panel.h"
#include "ui/settings/window_settings.h"
#include "ui/status_line.h"
#include "ui/stream_navigator/annotation_strip.h"
#include "ui/stream_navigator/effect_strip.h"
#include "ui/stream_navigator/frame_marks_strip.h"
#include "ui/stream_navigator/stream_navigator.h"
#include "ui/stream_navigator/timeline.h"
#include "ui/widgets/bar_overlay.h"
#include "ui/widgets/message_bar.h"
#include "ui/widgets/scroll_area.h"

#include <QCloseEvent>
#include <QDockWidget>
#include <QGuiApplication>
#include <QMenu>
#include <QMenuBar>
#include <QMimeData>
#include <QScreen>
#include <QScrollArea>
#include <QStatusBar>
#include <QToolBar>
#include <QVBoxLayout>

namespace fieldsight::ui {

MainWindow::MainWindow(const Pipeline& pipeline, const std::vector<ToolFactory>& tools,
                       QWidget* parent)
    : QMainWindow(parent)
{
    setObjectName(QStringLiteral("fieldsight_main_window"));
    setAcceptDrops(true);
    m_session = new EditingSession(pipeline, this);
    m_tools = new ToolManager(*m_session, tools, this);
    m_recorder = new FrameRecorder(m_session->stream(), this);
    buildCentre();
    const MenuTarget target{
        *m_session,
        *m_tools,
        this,
        [this](const QString& m, bool error) { showMessage(m, error); },
        [this](const QString& m, int ms) { statusBar()->showMessage(m, ms); },
        [this] { clearMessage(); },
        [this] { return m_message_bar->isVisible() ? m_message_bar->text() : QString(); }};
    m_annotation_files = new AnnotationsFile(target, *m_annotations_recovery_bar);
    m_files = new SessionFiles(target, *m_annotation_files, *m_view, *m_recovery_bar);
    connect(m_files, &SessionFiles::settingsToSave, this, &MainWindow::saveSettings);
    m_calibrate = new CalibrateActions(target);
    m_fit = new FitActions(target);
    m_disk_watch = new DiskWatch(target, *m_annotation_files, *m_files, *m_disk_bar);
    new StatusLine(*statusBar(), *m_session, *m_timeline, *m_view, *m_tools);
    buildDocks();
    m_highlights =
        new CellHighlights(*m_view, m_session->stream(), m_uv->canvas().selection(), this);
    connect(m_files, &SessionFiles::compareCellsChosen, this, &MainWindow::showCompareCells);
    const MenuParts parts{*m_view,      *m_navigator,  *m_files,     *m_annotation_files,
                          *m_recorder,  *m_calibrate,  *m_fit,       *m_lut_panel,
                          *m_bookmarks, *m_evaluation, *m_docks_menu};
    QMenuBar& bar = *menuBar();
    addFileMenu(bar, target, parts);
    addEditMenu(bar, target, parts);
    addViewMenu(bar, target, parts);
    addNavigateMenu(bar, parts);
    addObjectMenu(bar, target);
    addPipelineMenu(bar, target, parts);
    addCalibrateMenu(bar, parts);
    addAnnotateMenu(bar, target);
    addHelpMenu(bar, target);

    // The window shows what the documents say; it relays nothing between them.
    StreamDocument& stream = m_session->stream();
    LutDocument& lut = m_session->lut();
    connect(&stream, &StreamDocument::streamChanged, this, &MainWindow::onStreamChanged);
    connect(&stream, &StreamDocument::frameReady, this, &MainWindow::onFrameReady);
    connect(&lut, &LutDocument::modifiedChanged, this, &MainWindow::updateTitle);
    connect(&lut, &LutDocument::changed, this, &MainWindow::updateTitle);
    connect(&m_session->annotations(), &AnnotationsDocument::modifiedChanged, this,
            &MainWindow::updateTitle);
    const auto error = [this](const QString& m) { showMessage(m); };
    const auto note = [this](const QString& m) { showMessage(m, false); };
    connect(m_session, &EditingSession::problem, this, error);
    connect(m_session, &EditingSession::notice, this, note);
    connect(m_recorder, &FrameRecorder::problem, this, error);
    connect(m_pipeline, &PipelinePanel::problem, this, error);
    connect(m_lut_panel, &LutPanel::problem, this, error);
    connect(m_lut_panel, &LutPanel::notice, this, note);
    connect(m_view, &FrameView::painted, this, [this] {
        QMetaObject::invokeMethod(this, &MainWindow::refreshPanels, Qt::QueuedConnection);
    });
    connect(m_view, &FrameView::pixelHovered, this, [this](QPoint p) {
        m_hover = p;
        // The inspector lists each stage's shapes under the pixel, shown or not.
        m_session->stream().setAllLayersWanted(m_inspector->isVisible());
        m_inspector->inspect(m_session->stream().current().get(), p);
    });
    connect(m_view, &FrameView::hoverLeft, this, [this] {
        m_hover.reset();
        m_session->stream().setAllLayersWanted(false);
        m_inspector->clearPixel();
    });
    connect(&m_uv->canvas(), &UvCanvas::selectionChanged, m_highlights, &CellHighlights::refresh);
    connect(m_lut_panel, &LutPanel::cellsToOutline, &m_uv->canvas(), &UvCanvas::setOutlinedCells);

    restoreSettings();
    updateTitle();
    m_files->offerRecovery();
}

MainWindow::~MainWindow() = default;

void MainWindow::buildCentre()
{
    auto* central = new QWidget(this);
    auto* column = new QVBoxLayout(central);
    column->setContentsMargins(0, 0, 0, 0);
    column->setSpacing(0);
    m_view = new FrameView(central);
    m_view->setObjectName(QStringLiteral("frame_view"));
    m_view->setTools(m_tools);
    m_view->setStream(m_session->stream());
    m_view->setAnnotations(m_session->annotations());
    column->addWidget(m_view, 1);
    // The bars float over the view's top: one appearing never moves the frame under the mouse.
    auto* bars = new BarOverlay(m_view);
    m_message_bar = new MessageBar(bars);
    bars->addBar(m_message_bar);
    // Unsaved LUT edits of a session that ended without saving them: offered, never forced.
    m_recovery_bar = new OfferBar(tr("Recover"), tr("Discard"), bars);
    m_recovery_bar->setObjectName(QStringLiteral("recovery_bar"));
    bars->addBar(m_recovery_bar);
    m_annotations_recovery_bar = new OfferBar(tr("Recover"), tr("Discard"), bars);
    m_annotations_recovery_bar->setObjectName(QStringLiteral("annotations_recovery_bar"));
    bars->addBar(m_annotations_recovery_bar);
    m_disk_bar = new OfferBar(tr("Reload"), tr("Keep mine"), bars);
    m_disk_bar->setObjectName(QStringLiteral("disk_bar"));
    bars->addBar(m_disk_bar);
    m_navigator = new StreamNavigator(m_session->stream(), central);
    column->addWidget(m_navigator);
    setCentralWidget(central);
    m_timeline = std::make_unique<Timeline>(*m_session, *m_navigator);
}

void MainWindow::buildDocks()
{
    auto dock = [this](QWidget* content, const QString& title, const QString& name,
                       Qt::DockWidgetArea area) {
        auto* d = new QDockWidget(title, this);
        d->setObjectName(name);
        d->setWidget(content);
        addDockWidget(area, d);
        return d;
    };
    EditingSession& s = *m_session;
    m_layers = new LayersPanel(s.pipeline(), this);
    connect(m_layers, &LayersPanel::visibleLayersChanged, m_view, &FrameView::setVisibleLayers);
    connect(m_layers, &LayersPanel::visibleLayersChanged, &s.stream(),
            &StreamDocument::setLayersShown);
    QDockWidget* layers = dock(m_layers, tr("Layers"), "layers_dock", Qt::LeftDockWidgetArea);
    m_inspector = new InspectorPanel(s.pipeline(), this);
    QDockWidget* inspector = dock(inScrollArea(m_inspector), tr("Pixel inspector"),
                                  "inspector_dock", Qt::LeftDockWidgetArea);
    m_bookmarks = new BookmarksPanel(s.bookmarks(), s.stream(), this);
    QDockWidget* bookmarks =
        dock(m_bookmarks, tr("Bookmarks"), "bookmarks_dock", Qt::LeftDockWidgetArea);
    m_history = new HistoryPanel(s, this);
    QDockWidget* history = dock(m_history, tr("History"), "history_dock", Qt::LeftDockWidgetArea);
    m_evaluation = new EvaluationPanel(s.evaluation(), s.stream(), this);
    // Tabbed with the layers, where there is height for its list; scrolled all the same.
    QDockWidget* evaluation = dock(inScrollArea(m_evaluation), tr("Evaluation"), "evaluation_dock",
                                   Qt::LeftDockWidgetArea);
    // The chosen disagreement's culprits over the frame; its frames on the timeline.
    connect(m_evaluation, &EvaluationPanel::highlightChanged, m_view, [this](const QImage& image) {
        m_view->setHighlight(QStringLiteral("evaluation"), image);
    });
    connect(m_evaluation, &EvaluationPanel::culpritsAt, m_view, [this](const QRect& r) {
        // Centred when they are not all in sight (zoomed in on another part of the frame).
        if (!m_view->shows(r))
            m_view->centreOn(QRectF(r).center());
    });
    connect(m_evaluation, &EvaluationPanel::marksChanged, this, [this] {
        m_timeline->showEvaluation(m_evaluation->frameMarks(), m_evaluation->changeText());
    });
    connect(&m_timeline->disagreementStrip(), &FrameMarksStrip::frameClicked, m_evaluation,
            &EvaluationPanel::showFrame);

    m_pipeline = new PipelinePanel(s.stream(), s.settings(), this);
    QDockWidget* pipeline =
        dock(m_pipeline, tr("Pipeline"), "pipeline_dock", Qt::RightDockWidgetArea);
    m_detections = new DetectionsPanel(this);
    connect(m_detections, &DetectionsPanel::detectionActivated, m_view,
            [this](const QRectF& r) { m_view->centreOn(r.center() + QPointF(0.5, 0.5)); });
    QDockWidget* detections =
        dock(m_detections, tr("Detections"), "detections_dock", Qt::RightDockWidgetArea);
    m_lut_panel = new LutPanel(s.lut(), s.stream(), s.samples(), *m_tools, this);
    // Scrolled, so the editor's many controls fit a small laptop screen.
    auto* lut_scroll = new QScrollArea(this);
    lut_scroll->setWidget(m_lut_panel);
    lut_scroll->setWidgetResizable(true);
    lut_scroll->setFrameShape(QFrame::NoFrame);
    QDockWidget* lut = dock(lut_scroll, tr("LUT editor"), "lut_dock", Qt::RightDockWidgetArea);
    m_uv = new UvPlanePanel(s.lut(), s.stream(), *m_tools, this);
    QDockWidget* uv = dock(m_uv, tr("UV plane"), "uv_dock", Qt::RightDockWidgetArea);

    tabifyDockWidget(layers, bookmarks);
    tabifyDockWidget(layers, history);
    tabifyDockWidget(layers, evaluation);
    layers->raise();
    splitDockWidget(pipeline, detections, Qt::Vertical);
    tabifyDockWidget(pipeline, lut); // after the split, or the detections join the tabs
    tabifyDockWidget(detections, uv);
    pipeline->raise();
    detections->raise();
    resizeDocks({layers, pipeline}, {270, 340}, Qt::Horizontal);
    resizeDocks({layers, inspector}, {480, 200}, Qt::Vertical);
    // The editing docks (pipeline, LUT editor) get the most height: every LUT control shows
    // without scrolling at 1280x800.
    resizeDocks({pipeline, detections}, {600, 160}, Qt::Vertical);

    // The annotation tools' buttons, beside the frame they draw on.
    auto* annotate = new QToolBar(tr("Annotation tools"), this);
    annotate->setObjectName(QStringLiteral("annotate_toolbar"));
    annotate->addActions(m_tools->actions(QStringLiteral("annotate")));
    addToolBar(Qt::LeftToolBarArea, annotate);

    m_docks_menu = new QMenu(tr("Panels"), this);
    for (QDockWidget* d :
         {layers, bookmarks, history, inspector, pipeline, lut, detections, uv, evaluation})
        m_docks_menu->addAction(d->toggleViewAction());
    m_docks_menu->addAction(annotate->toggleViewAction());
}

void MainWindow::showMessage(const QString& text, bool error)
{
    m_last_message = text;
    m_message_bar->show(text, error);
    statusBar()->showMessage(text, 8000);
}

void MainWindow::clearMessage()
{
    if (m_standing_problem.isEmpty())
        m_message_bar->hide();
    else
        showMessage(m_standing_problem);
}

void MainWindow::showCompareCells(const std::vector<std::uint32_t>& cells)
{
    m_uv->canvas().setOutlinedCells(cells);
    m_highlights->setCompareCells(cells);
}

void MainWindow::onStreamChanged()
{
    m_detections->showOutput(nullptr);
    updateTitle();
}

void MainWindow::onFrameReady()
{
    // The view first (its highlights are found again already); the panels follow once it has
    // painted (at once when it cannot paint).
    if (!m_view->isVisible())
        refreshPanels();
}

void MainWindow::refreshPanels()
{
    const auto& out = m_session->stream().current();
    if (out && m_detections->shownSerial() == out->serial)
        return; // a repaint of the same frame (hover, zoom)
    m_detections->showOutput(out.get());
    if (m_hover)
        m_inspector->inspect(out.get(), *m_hover);
}

void MainWindow::updateTitle()
{
    setWindowTitle(m_session->title());
    setWindowModified(m_session->unsavedEdits());
}

void MainWindow::saveSettings() const
{
    WindowSettings w;
    w.geometry = saveGeometry();
    w.state = saveState();
    w.layers = m_view->visibleLayers();
    w.mode = int(m_view->mode());
    w.labels = m_view->labelsShown();
    w.follow_light = m_session->lightScan().enabled();
    w.fps = m_navigator->speed();
    w.loop = m_navigator->loopAction()->isChecked();
    m_files->saveSettings(w);
    m_tools->saveSettings(w);
    w.fit_budget = m_fit->budget();
    w.save();
}

void MainWindow::restoreSettings()
{
    const WindowSettings w = WindowSettings::load();
    if (!w.problem.isEmpty()) {
        m_standing_problem = w.problem;
        showMessage(w.problem);
    }
    if (!restoreGeometry(w.geometry)) {
        // First run: 1280 x 800, or most of a smaller screen.
        QSize size(1280, 800);
        if (const QScreen* screen = QGuiApplication::primaryScreen())
            size = size.boundedTo(screen->availableSize() * 0.95);
        resize(size);
    }
    restoreState(w.state);
    m_layers->setVisibleLayers(w.layers ? *w.layers
                                        : LayersPanel::defaultLayers(m_session->pipeline()));
    m_view->setMode(ViewMode(w.mode));
    m_view->setLabelsShown(w.labels);
    m_session->lightScan().setEnabled(w.follow_light);
    m_navigator->setSpeed(w.fps);
    m_navigator->loopAction()->setChecked(w.loop);
    m_files->restoreSettings(w);
    m_fit->setBudget(w.fit_budget);
    m_tools->restoreSettings(w);
}

void MainWindow::closeEvent(QCloseEvent* event)
{
    if (!m_files->confirmLutChanges() || !m_annotation_files->confirmChanges()) {
        event->ignore();
        return;
    }
    m_navigator->setPlaying(false);
    saveSettings();
    event->accept();
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event)
{
    if (event->mimeData()->hasUrls() && event->mimeData()->urls().value(0).isLocalFile())
        event->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* event)
{
    const QList<QUrl> urls = event->mimeData()->urls();
    if (urls.isEmpty() || !urls.front().isLocalFile())
        return;
    m_files->openPath(urls.front().toLocalFile());
    event->acceptProposedAction();
}

} // namespace fieldsight::ui
