#include "ui/main_window.h"

#include "ui/adapters/local_path.h"

#include "ui/panels/detections_panel.h"
#include "ui/panels/inspector_panel.h"
#include "ui/panels/layers_panel.h"
#include "ui/panels/lut_panel.h"
#include "ui/panels/pipeline_panel.h"
#include "ui/adapters/image_adapter.h"
#include "ui/document/frame_recorder.h"
#include "ui/panels/lut_compare_dialog.h"
#include "ui/panels/uv_plane_panel.h"
#include "visioncore/io/lut_import.h"
#include "ui/stream_navigator/effect_strip.h"
#include "ui/stream_navigator/stream_navigator.h"
#include "visioncore/basics/atomic_file.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QBuffer>
#include <QClipboard>
#include <QScrollArea>
#include <QCloseEvent>
#include <QDir>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QInputDialog>
#include <QLabel>
#include <QListWidget>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QProgressDialog>
#include <QPushButton>
#include <QScreen>
#include <QSettings>
#include <QStatusBar>
#include <QToolButton>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>

namespace fieldsight::ui {

namespace {

constexpr int kMaxRecent = 10;

QString qs(const std::string& s)
{
    return QString::fromStdString(s);
}

/// A path as a setting: its exact bytes, since settings files store text as UTF-8.
QVariant pathSetting(const QString& path)
{
    return QByteArray::fromStdString(toLocalPath(path));
}

/// A path read back from pathSetting() (or a plain string, as older settings hold it).
QString pathFromSetting(const QVariant& value)
{
    return value.typeId() == QMetaType::QByteArray
               ? fromLocalPath(value.toByteArray().toStdString())
               : value.toString();
}

QStringList toList(const LayerSet& layers)
{
    QStringList list;
    for (const std::string& id : layers)
        list << qs(id);
    return list;
}

/// A menu item with a shortcut, calling `fn` on `receiver`.
template <class Receiver, class Fn>
QAction* addItem(QMenu* menu, const QString& text, const QKeySequence& key,
                 const Receiver* receiver, Fn fn)
{
    QAction* action = menu->addAction(text);
    action->setShortcut(key);
    QObject::connect(action, &QAction::triggered, receiver, fn);
    return action;
}

bool isLutFile(const QString& path)
{
    const QString lower = path.toLower();
    for (std::string_view suffix : importableLutSuffixes())
        if (lower.endsWith(QString::fromLatin1(suffix.data(), qsizetype(suffix.size()))))
            return true;
    return false;
}

} // namespace

MainWindow::MainWindow(const Pipeline& pipeline, QWidget* parent) : QMainWindow(parent)
{
    setObjectName(QStringLiteral("fieldsight_main_window"));
    setAcceptDrops(true);
    m_doc = new StreamDocument(pipeline, this);
    m_lut_doc = new LutDocument(this);

    auto* central = new QWidget(this);
    auto* column = new QVBoxLayout(central);
    column->setContentsMargins(0, 0, 0, 0);
    column->setSpacing(0);

    m_message_bar = new QWidget(central);
    m_message_bar->setObjectName(QStringLiteral("message_bar"));
    m_message_bar->setAutoFillBackground(true);
    auto* bar = new QHBoxLayout(m_message_bar);
    bar->setContentsMargins(8, 4, 4, 4);
    m_message = new QLabel(m_message_bar);
    m_message->setWordWrap(true);
    m_message->setTextInteractionFlags(Qt::TextSelectableByMouse);
    bar->addWidget(m_message, 1);
    auto* close = new QToolButton(m_message_bar);
    close->setText(QStringLiteral("✕"));
    close->setAutoRaise(true);
    connect(close, &QToolButton::clicked, m_message_bar, &QWidget::hide);
    bar->addWidget(close);
    m_message_bar->hide();
    column->addWidget(m_message_bar);

    // Unsaved LUT edits of a session that ended without saving them: offered, never forced.
    m_recovery_bar = new QWidget(central);
    m_recovery_bar->setObjectName(QStringLiteral("recovery_bar"));
    m_recovery_bar->setAutoFillBackground(true);
    QPalette recovery_palette = m_recovery_bar->palette();
    recovery_palette.setColor(QPalette::Window, QColor(255, 244, 200));
    recovery_palette.setColor(QPalette::WindowText, QColor(20, 20, 20));
    m_recovery_bar->setPalette(recovery_palette);
    auto* recovery_row = new QHBoxLayout(m_recovery_bar);
    recovery_row->setContentsMargins(8, 4, 4, 4);
    m_recovery_label = new QLabel(m_recovery_bar);
    m_recovery_label->setWordWrap(true);
    recovery_row->addWidget(m_recovery_label, 1);
    auto* recover = new QPushButton(tr("Recover"), m_recovery_bar);
    recover->setObjectName(QStringLiteral("recover_lut"));
    connect(recover, &QPushButton::clicked, this, &MainWindow::recoverLut);
    recovery_row->addWidget(recover);
    auto* discard = new QPushButton(tr("Discard"), m_recovery_bar);
    discard->setObjectName(QStringLiteral("discard_recovery"));
    connect(discard, &QPushButton::clicked, this, [this] {
        m_lut_doc->discardRecovery();
        m_recovery_bar->hide();
    });
    recovery_row->addWidget(discard);
    m_recovery_bar->hide();
    column->addWidget(m_recovery_bar);

    m_view = new FrameView(central);
    m_view->setObjectName(QStringLiteral("frame_view"));
    column->addWidget(m_view, 1);
    m_navigator = new StreamNavigator(*m_doc, central);
    column->addWidget(m_navigator);
    setCentralWidget(central);
    m_effect = new EditEffectScan(m_doc->pipeline(), this);
    m_recorder = new FrameRecorder(*m_doc, this);
    connect(m_recorder, &FrameRecorder::problem, this,
            [this](const QString& m) { showMessage(m); });
    connect(m_doc, &StreamDocument::notice, this,
            [this](const QString& m) { showMessage(m, false); });
    m_effect_strip = new EffectStrip(*m_effect, *m_navigator->slider(), m_navigator);
    m_navigator->addTimelineStrip(m_effect_strip);
    connect(m_effect, &EditEffectScan::updated, this,
            [this] { m_status_effect->setText(m_effect_strip->summary()); });
    connect(m_effect_strip, &EffectStrip::frameClicked, m_navigator, &StreamNavigator::goToFrame);
    connect(m_navigator->slider(), &QSlider::valueChanged, m_effect_strip,
            qOverload<>(&QWidget::update));

    m_status_zoom = new QLabel(this);
    m_status_time = new QLabel(this);
    m_status_effect = new QLabel(this);
    m_status_effect->setObjectName(QStringLiteral("effect_summary"));
    statusBar()->addWidget(m_status_effect, 1);
    statusBar()->addPermanentWidget(m_status_time);
    statusBar()->addPermanentWidget(m_status_zoom);

    buildDocks();
    buildMenus();

    connect(m_doc, &StreamDocument::streamChanged, this, &MainWindow::onStreamChanged);
    connect(m_doc, &StreamDocument::lutChanged, this, &MainWindow::onLutLoaded);
    connect(m_lut_doc, &LutDocument::changed, this, [this] {
        m_doc->setEditedLut(m_lut_doc->version());
        m_effect->edited(m_lut_doc->editBase(), m_lut_doc->version());
    });
    connect(m_doc, &StreamDocument::settingsChanged, this, [this] {
        m_effect->setSettings(std::make_shared<ParamSet>(m_doc->paramChanges()),
                              m_doc->skippedStages());
    });
    connect(m_lut_doc, &LutDocument::modifiedChanged, this, &MainWindow::updateTitle);
    connect(m_lut_doc, &LutDocument::problem, this, [this](const QString& m) { showMessage(m); });
    connect(m_view, &FrameView::toolPressed, m_lut_panel, &LutPanel::press);
    connect(m_view, &FrameView::toolDragged, m_lut_panel, &LutPanel::drag);
    connect(m_view, &FrameView::toolReleased, m_lut_panel, &LutPanel::release);
    connect(m_view, &FrameView::pixelPicked, m_lut_panel, &LutPanel::pick);
    connect(m_lut_panel, &LutPanel::toolChanged, this, [this](bool editing, int radius) {
        m_view->setToolActive(editing);
        m_view->setBrushRadius(radius);
    });
    connect(m_doc, &StreamDocument::frameReady, this, &MainWindow::onFrameReady);
    connect(m_doc, &StreamDocument::bookmarksChanged, this, &MainWindow::refreshBookmarks);
    connect(m_view, &FrameView::zoomChanged, this, [this](double zoom) {
        m_status_zoom->setText(tr("zoom %1%").arg(zoom * 100, 0, 'f', 0));
    });
    connect(m_view, &FrameView::painted, this, [this] {
        QMetaObject::invokeMethod(this, &MainWindow::refreshPanels, Qt::QueuedConnection);
    });
    connect(m_view, &FrameView::pixelHovered, this, [this](QPoint p) {
        m_hover = p;
        m_inspector->inspect(m_doc->current().get(), p);
        refreshPreview();
    });
    connect(m_view, &FrameView::hoverLeft, this, [this] {
        m_hover.reset();
        m_inspector->clearPixel();
        refreshPreview();
    });
    // Linked both ways: what the image tool would change shows in the image and in the UV
    // plane; cells selected in the UV plane light up their pixels in the image.
    connect(m_lut_panel, &LutPanel::previewChanged, this,
            [this](const cv::Mat& pixels, const std::vector<std::uint32_t>& cells) {
                m_view->setHighlight(QStringLiteral("preview"),
                                     maskToQImage(pixels, QColor(255, 0, 255, 150)));
                m_uv->canvas().setOutlinedCells(cells);
                // Also in the status bar: the editor's own line may be scrolled out of sight.
                if (const QString text = m_lut_panel->previewText(); !text.isEmpty())
                    statusBar()->showMessage(text);
                else if (!m_preview_shown.isEmpty() &&
                         statusBar()->currentMessage() == m_preview_shown)
                    statusBar()->clearMessage();
                m_preview_shown = m_lut_panel->previewText();
            });
    connect(&m_uv->canvas(), &UvCanvas::selectionChanged, this, &MainWindow::refreshCellHighlights);
    connect(m_lut_doc, &LutDocument::changed, this, &MainWindow::refreshPreview);
    connect(m_lut_panel, &LutPanel::cellsToOutline, this,
            [this](const std::vector<std::uint32_t>& cells) {
                m_uv->canvas().setOutlinedCells(cells);
            });
    connect(m_lut_panel, &LutPanel::toolChanged, this, &MainWindow::refreshPreview);
    connect(m_pipeline, &PipelinePanel::problem, this,
            [this](const QString& m) { showMessage(m); });
    connect(m_lut_panel, &LutPanel::problem, this, [this](const QString& m) { showMessage(m); });

    restoreSettings();
    updateTitle();
    offerRecovery();
}

MainWindow::~MainWindow()
{
    // Opens still running (cancelled ones too) use the pipeline: let them end first.
    for (QFutureWatcherBase* watcher : findChildren<QFutureWatcherBase*>())
        watcher->waitForFinished();
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
    m_layers = new LayersPanel(m_doc->pipeline(), this);
    connect(m_layers, &LayersPanel::visibleLayersChanged, m_view, &FrameView::setVisibleLayers);
    QDockWidget* layers = dock(m_layers, tr("Layers"), "layers_dock", Qt::LeftDockWidgetArea);

    m_inspector = new InspectorPanel(m_doc->pipeline(), this);
    QDockWidget* inspector =
        dock(m_inspector, tr("Pixel inspector"), "inspector_dock", Qt::LeftDockWidgetArea);

    auto* marks = new QWidget(this);
    auto* marks_column = new QVBoxLayout(marks);
    marks_column->setContentsMargins(0, 0, 0, 0);
    m_bookmark_list = new QListWidget(marks);
    m_bookmark_list->setObjectName(QStringLiteral("bookmarks"));
    connect(m_bookmark_list, &QListWidget::itemActivated, this, [this](QListWidgetItem* item) {
        m_doc->setCurrentIndex(std::size_t(item->data(Qt::UserRole).toULongLong()));
    });
    marks_column->addWidget(m_bookmark_list, 1);
    auto* marks_row = new QHBoxLayout;
    auto* add = new QPushButton(tr("Mark frame…"), marks);
    connect(add, &QPushButton::clicked, this, &MainWindow::addBookmark);
    auto* remove = new QPushButton(tr("Remove"), marks);
    connect(remove, &QPushButton::clicked, this, [this] {
        if (QListWidgetItem* item = m_bookmark_list->currentItem())
            if (Status s = m_doc->removeBookmark(item->data(Qt::UserRole).toULongLong()); !s)
                showMessage(qs(s.error().message));
    });
    marks_row->addWidget(add);
    marks_row->addWidget(remove);
    marks_column->addLayout(marks_row);
    QDockWidget* bookmarks = dock(marks, tr("Bookmarks"), "bookmarks_dock", Qt::LeftDockWidgetArea);

    m_pipeline = new PipelinePanel(*m_doc, this);
    QDockWidget* pipeline =
        dock(m_pipeline, tr("Pipeline"), "pipeline_dock", Qt::RightDockWidgetArea);
    m_detections = new DetectionsPanel(this);
    connect(m_detections, &DetectionsPanel::detectionActivated, this, [this](const QRectF& r) {
        // Centre the view on the chosen detection.
        const QPointF centre = (r.center() + QPointF(0.5, 0.5)) * m_view->zoom();
        m_view->setImageOrigin((QPointF(m_view->rect().center()) - centre).toPoint());
    });
    QDockWidget* detections =
        dock(m_detections, tr("Detections"), "detections_dock", Qt::RightDockWidgetArea);

    m_lut_panel = new LutPanel(*m_lut_doc, *m_doc, this);
    // Scrolled, so the editor's many controls fit a small laptop screen.
    auto* lut_scroll = new QScrollArea(this);
    lut_scroll->setWidget(m_lut_panel);
    lut_scroll->setWidgetResizable(true);
    lut_scroll->setFrameShape(QFrame::NoFrame);
    QDockWidget* lut = dock(lut_scroll, tr("LUT editor"), "lut_dock", Qt::RightDockWidgetArea);
    m_uv = new UvPlanePanel(*m_lut_doc, *m_doc, *m_lut_panel, this);
    QDockWidget* uv = dock(m_uv, tr("UV plane"), "uv_dock", Qt::RightDockWidgetArea);

    tabifyDockWidget(layers, bookmarks);
    layers->raise();
    splitDockWidget(pipeline, detections, Qt::Vertical);
    tabifyDockWidget(pipeline, lut); // after the split, or the detections join the tabs
    tabifyDockWidget(detections, uv);
    pipeline->raise();
    detections->raise();
    resizeDocks({layers, pipeline}, {270, 340}, Qt::Horizontal);
    resizeDocks({layers, inspector}, {480, 200}, Qt::Vertical);

    m_docks_menu = new QMenu(tr("Panels"), this);
    for (QDockWidget* d : {layers, bookmarks, inspector, pipeline, lut, detections, uv})
        m_docks_menu->addAction(d->toggleViewAction());
}

void MainWindow::buildMenus()
{
    QMenu* file = menuBar()->addMenu(tr("&File"));
    QAction* open_folder = file->addAction(tr("Open stream folder…"), this, [this] {
        const QString dir = QFileDialog::getExistingDirectory(
            this, tr("Open stream folder"), QFileInfo(m_doc->streamSpec()).absolutePath());
        if (!dir.isEmpty())
            openStream(dir);
    });
    open_folder->setShortcut(QKeySequence::Open);
    addItem(file, tr("Open stream file (.strm, video)…"),
            QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_O), this, [this] {
                const QString path = QFileDialog::getOpenFileName(
                    this, tr("Open stream file"), QFileInfo(m_doc->streamSpec()).absolutePath(),
                    tr("Streams (*.strm *.avi *.mp4 *.mkv *.mov *.webm);;All files (*)"));
                if (!path.isEmpty())
                    openStream(path);
            });
    file->addAction(tr("Open camera…"), this, [this] {
        bool ok = false;
        const int n =
            QInputDialog::getInt(this, tr("Open camera"), tr("Camera number:"), 0, 0, 99, 1, &ok);
        if (ok)
            openStream(QStringLiteral("camera:%1").arg(n));
    });
    QAction* record = file->addAction(tr("Record camera to folder…"));
    record->setObjectName(QStringLiteral("record_camera"));
    record->setCheckable(true);
    record->setToolTip(tr("Write every camera frame shown (play to record continuously) into a "
                          "stream folder, with the LUT in use"));
    connect(record, &QAction::triggered, this, [this, record](bool on) {
        if (!on) {
            if (Status s = m_recorder->stop(); !s)
                showMessage(QString::fromStdString(s.error().message));
            else
                showMessage(tr("Recorded %1 frames to %2")
                                .arg(qulonglong(m_recorder->frames()))
                                .arg(m_recorder->path()),
                            false);
            return;
        }
        const QString folder =
            QFileDialog::getExistingDirectory(this, tr("Record camera frames into"));
        Status s = folder.isEmpty() ? Status(Error{"no folder chosen"})
                                    : m_recorder->start(folder, m_lut_doc->table());
        if (!s && !folder.isEmpty())
            showMessage(QString::fromStdString(s.error().message));
        record->setChecked(m_recorder->recording());
    });
    connect(m_recorder, &FrameRecorder::stateChanged, record, &QAction::setChecked);
    connect(m_doc, &StreamDocument::streamChanged, record,
            [this, record] { record->setEnabled(m_doc->live()); });
    record->setEnabled(false);
    QString lut_filter = tr("Colour tables (");
    for (std::string_view suffix : importableLutSuffixes())
        lut_filter += QStringLiteral("*%1 ").arg(
            QString::fromLatin1(suffix.data(), qsizetype(suffix.size())));
    lut_filter += QStringLiteral(");;") + tr("All files (*)");
    addItem(file, tr("Open LUT…"), QKeySequence(Qt::CTRL | Qt::Key_L), this, [this, lut_filter] {
        const QString path = QFileDialog::getOpenFileName(
            this, tr("Open LUT"), QFileInfo(m_doc->lutPath()).absolutePath(), lut_filter);
        if (!path.isEmpty())
            openLut(path);
    });
    file->addAction(tr("Compare with LUT…"), this, [this, lut_filter] {
        const QString path = QFileDialog::getOpenFileName(
            this, tr("Compare with LUT"), QFileInfo(m_doc->lutPath()).absolutePath(), lut_filter);
        if (!path.isEmpty())
            compareLut(path);
    });
    addItem(file, tr("Save LUT"), QKeySequence::Save, this, [this] { (void)saveLut(); });
    addItem(file, tr("Save LUT as…"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S), this,
            [this] { (void)saveLutAs(); });
    m_recent_menu = file->addMenu(tr("Recent streams"));
    file->addSeparator();
    addItem(file, tr("Save view as PNG…"), QKeySequence(Qt::CTRL | Qt::Key_E), this, [this] {
        const QString name = QStringLiteral("%1_%2.png")
                                 .arg(QFileInfo(m_doc->streamSpec()).completeBaseName())
                                 .arg(m_doc->currentIndex(), 6, 10, QLatin1Char('0'));
        const QString path = QFileDialog::getSaveFileName(this, tr("Save view as PNG"), name,
                                                          tr("PNG images (*.png)"));
        if (!path.isEmpty())
            saveSnapshot(path);
    });
    addItem(file, tr("Copy view"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_C), this,
            &MainWindow::copySnapshot);
    file->addSeparator();
    addItem(file, tr("Quit"), QKeySequence::Quit, this, &QWidget::close);

    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    QAction* undo = m_lut_doc->undoStack().createUndoAction(this, tr("Undo"));
    undo->setShortcuts(QKeySequence::Undo);
    QAction* redo = m_lut_doc->undoStack().createRedoAction(this, tr("Redo"));
    redo->setShortcuts(QKeySequence::Redo); // Ctrl+Y and Ctrl+Shift+Z on Linux
    edit->addAction(undo);
    edit->addAction(redo);
    edit->addSeparator();
    QMenu* classes = edit->addMenu(tr("Colour class"));
    classes->addActions(m_lut_panel->colourActions());
    QMenu* tools = edit->addMenu(tr("LUT tool"));
    const std::pair<QString, LutTool> tool_list[] = {
        {tr("Pan"), LutTool::Navigate},    {tr("Click with tolerance"), LutTool::Click},
        {tr("Brush"), LutTool::Brush},     {tr("Erase"), LutTool::Erase},
        {tr("Magic wand"), LutTool::Wand}, {tr("Sample region"), LutTool::Sample}};
    const Qt::Key tool_keys[] = {Qt::Key_P, Qt::Key_C, Qt::Key_B, Qt::Key_E, Qt::Key_W, Qt::Key_S};
    for (std::size_t i = 0; i < std::size(tool_list); ++i) {
        const LutTool t = tool_list[i].second;
        addItem(tools, tool_list[i].first, QKeySequence(tool_keys[i]), this,
                [this, t] { m_lut_panel->setTool(t); });
    }

    QMenu* view = menuBar()->addMenu(tr("&View"));
    auto* modes = new QActionGroup(this);
    const std::pair<QString, ViewMode> mode_list[] = {{tr("Raw"), ViewMode::Raw},
                                                      {tr("Classified"), ViewMode::Classified},
                                                      {tr("Side by side"), ViewMode::SideBySide},
                                                      {tr("Blend"), ViewMode::Blend}};
    int key = Qt::Key_1;
    for (const auto& [text, mode] : mode_list) {
        QAction* a = addItem(view, text, QKeySequence(Qt::ALT | key++), this,
                             [this, mode = mode] { setMode(mode); });
        a->setCheckable(true);
        a->setData(int(mode));
        modes->addAction(a);
        m_mode_actions << a;
    }
    m_mode_actions.front()->setChecked(true);
    view->addSeparator();
    addItem(view, tr("Zoom in"), QKeySequence::ZoomIn, m_view, &FrameView::zoomIn);
    addItem(view, tr("Zoom out"), QKeySequence::ZoomOut, m_view, &FrameView::zoomOut);
    addItem(view, tr("Fit to window"), QKeySequence(Qt::CTRL | Qt::Key_0), m_view,
            &FrameView::fitToWindow);
    addItem(view, tr("Actual pixels (100%)"), QKeySequence(Qt::CTRL | Qt::Key_1), this,
            [this] { m_view->setZoom(1); });
    m_labels_action = addItem(view, tr("Detection labels"), QKeySequence(Qt::Key_T), m_view,
                              &FrameView::setLabelsShown);
    m_labels_action->setCheckable(true);
    m_labels_action->setChecked(true);
    view->addSeparator();
    view->addMenu(m_docks_menu);

    QMenu* nav = menuBar()->addMenu(tr("&Navigate"));
    nav->addActions(m_navigator->navigationActions());
    nav->addSeparator();
    addItem(nav, tr("Bookmark this frame…"), QKeySequence(Qt::CTRL | Qt::Key_B), this,
            &MainWindow::addBookmark);
    addItem(nav, tr("Next bookmark"), QKeySequence(Qt::Key_BracketRight), this,
            [this] { jumpBookmark(1); });
    addItem(nav, tr("Previous bookmark"), QKeySequence(Qt::Key_BracketLeft), this,
            [this] { jumpBookmark(-1); });

    QMenu* pipe = menuBar()->addMenu(tr("&Pipeline"));
    addItem(pipe, tr("Run this frame again"), QKeySequence(Qt::Key_F5), m_doc,
            &StreamDocument::rerun);
    pipe->addAction(tr("Reset every parameter"), this,
                    [this] { (void)m_doc->setParamChanges({}); });
    pipe->addAction(tr("Reset the running means"), this, [this] {
        m_doc->resetMeans();
        onFrameReady();
    });
    pipe->addAction(tr("Save parameters…"), this, [this] {
        const QString path =
            QFileDialog::getSaveFileName(this, tr("Save parameters"), QStringLiteral("params.json"),
                                         tr("Parameter sets (*.json)"));
        if (path.isEmpty())
            return;
        if (Status s = m_doc->paramChanges().save(toLocalPath(path)); !s)
            showMessage(qs(s.error().message));
        else
            showMessage(tr("Saved the parameters to %1").arg(path), false);
    });
    pipe->addAction(tr("Load parameters…"), this, [this] {
        const QString path = QFileDialog::getOpenFileName(this, tr("Load parameters"), {},
                                                          tr("Parameter sets (*.json)"));
        if (path.isEmpty())
            return;
        auto params = ParamSet::load(toLocalPath(path));
        Status s = params ? m_doc->setParamChanges(params.value()) : Status(params.error());
        if (!s)
            showMessage(qs(s.error().message));
    });

    QMenu* help = menuBar()->addMenu(tr("&Help"));
    help->addAction(tr("Keyboard shortcuts"), this, [this] {
        QString text;
        for (QMenu* menu : menuBar()->findChildren<QMenu*>())
            for (QAction* a : menu->actions())
                if (!a->shortcut().isEmpty())
                    text += QStringLiteral("%1\t%2\n")
                                .arg(a->shortcut().toString(QKeySequence::NativeText),
                                     a->text().remove('&'));
        QMessageBox::information(this, tr("Keyboard shortcuts"), text);
    });
    help->addAction(tr("About Fieldsight"), this, [this] {
        QMessageBox::about(this, tr("About Fieldsight"),
                           tr("Fieldsight %1: a colour-segmentation robot vision debugger.")
                               .arg(QCoreApplication::applicationVersion()));
    });
}

void MainWindow::setMode(ViewMode mode)
{
    m_view->setMode(mode);
    for (QAction* a : m_mode_actions)
        a->setChecked(a->data().toInt() == int(mode));
}

void MainWindow::showMessage(const QString& text, bool error)
{
    m_last_message = text;
    QPalette pal = m_message_bar->palette();
    pal.setColor(QPalette::Window, error ? QColor(255, 222, 222) : QColor(222, 240, 255));
    pal.setColor(QPalette::WindowText, QColor(20, 20, 20));
    m_message_bar->setPalette(pal);
    m_message->setPalette(pal);
    m_message->setText(text);
    m_message_bar->show();
    statusBar()->showMessage(text, 8000);
}

QString MainWindow::bundledSampleStream()
{
    const QString app = QCoreApplication::applicationDirPath();
    const QStringList candidates{
        qEnvironmentVariable("FIELDSIGHT_SAMPLE_STREAM"),
        app + QStringLiteral("/../share/fieldsight/sample_streams/lab1"),
        app + QStringLiteral("/../../sample_streams/lab1"),
        app + QStringLiteral("/../sample_streams/lab1"),
        QStringLiteral(FIELDSIGHT_SOURCE_SAMPLE_STREAMS "/lab1"),
    };
    for (const QString& c : candidates)
        if (isLocalFolder(c))
            return QDir::cleanPath(QFileInfo(c).absoluteFilePath());
    return {};
}

void MainWindow::openLastSession()
{
    const QSettings settings;
    const QString last = pathFromSetting(settings.value(QStringLiteral("session/stream")));
    if (localPathExists(last)) {
        QString lut = pathFromSetting(settings.value(QStringLiteral("session/lut")));
        if (!localPathExists(lut))
            lut.clear();
        openStream(last, lut);
        return;
    }
    const QString sample = bundledSampleStream();
    if (sample.isEmpty()) {
        showMessage(tr("The bundled sample stream was not found; open a stream with File > "
                       "Open stream folder"));
        return;
    }
    openStream(sample);
}

void MainWindow::openStream(const QString& spec, const QString& lut)
{
    if (!confirmLutChanges())
        return;
    if (m_open_watcher) {
        showMessage(tr("Still opening %1; wait or cancel it first").arg(m_opening));
        return;
    }
    m_opening = spec;
    m_open_watcher = new QFutureWatcher<Opening>(this);
    m_open_progress = new QProgressDialog(tr("Opening %1…").arg(spec), tr("Cancel"), 0, 0, this);
    m_open_progress->setWindowTitle(tr("Opening stream"));
    m_open_progress->setMinimumDuration(400);
    m_open_progress->setWindowModality(Qt::WindowModal);
    const Pipeline& pipeline = m_doc->pipeline();
    connect(m_open_progress, &QProgressDialog::canceled, this, [this] {
        // The stream before stays open; the open runs to its end in the background and is
        // dropped.
        showMessage(tr("Opening %1 was cancelled").arg(m_opening), false);
        m_open_watcher->disconnect(this);
        auto* watcher = m_open_watcher;
        connect(watcher, &QFutureWatcherBase::finished, watcher, &QObject::deleteLater);
        m_open_watcher = nullptr;
        m_open_progress->deleteLater();
        m_open_progress = nullptr;
        emit streamOpened(false);
    });
    connect(m_open_watcher, &QFutureWatcherBase::finished, this, [this, spec, lut] {
        const Opening result = m_open_watcher->result();
        m_open_watcher->deleteLater();
        m_open_watcher = nullptr;
        if (m_open_progress) {
            m_open_progress->reset();
            m_open_progress->deleteLater();
            m_open_progress = nullptr;
        }
        if (!result.stream) {
            showMessage(result.error);
            emit streamOpened(false);
            return;
        }
        m_doc->adopt(result.stream);
        rememberRecent(spec);
        QStringList warnings = m_doc->warnings();
        if (const QString samples = m_lut_panel->sampler().loadProblem(); !samples.isEmpty())
            warnings << samples;
        if (!warnings.isEmpty())
            showMessage(warnings.join('\n'));
        else
            m_message_bar->hide();
        emit streamOpened(true);
    });
    m_open_watcher->setFuture(QtConcurrent::run([spec, lut, &pipeline] {
        Opening o;
        auto opened = StreamDocument::openSource(spec, lut, pipeline);
        if (opened)
            o.stream = std::move(opened).value();
        else
            o.error = qs(opened.error().message);
        return o;
    }));
}

LutCompareDialog* MainWindow::compareLut(const QString& path)
{
    auto other = importLut(toLocalPath(path));
    if (!other) {
        showMessage(QString::fromStdString(other.error().message));
        return nullptr;
    }
    auto* dialog = new LutCompareDialog(*m_lut_doc, std::move(other).value(), path, this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &LutCompareDialog::cellsChosen, this,
            [this](const std::vector<std::uint32_t>& cells) {
                m_uv->canvas().setOutlinedCells(cells);
                m_compare_cells.reset();
                if (!cells.empty())
                    m_compare_cells = CellMask::of(cells);
                refreshCellHighlights();
            });
    dialog->show();
    return dialog;
}

bool MainWindow::openLut(const QString& path)
{
    if (!confirmLutChanges())
        return false;
    if (Status s = m_doc->openLut(path); !s) {
        showMessage(qs(s.error().message));
        return false;
    }
    return true;
}

void MainWindow::openPath(const QString& path)
{
    if (isLutFile(path))
        openLut(path);
    else
        openStream(path);
}

void MainWindow::onStreamChanged()
{
    m_effect->setStream({}, nullptr); // scanned again once its LUT is in (onLutLoaded)
    m_view->setOutput(nullptr);
    m_view->fitToWindow();
    m_detections->showOutput(nullptr);
    updateTitle();
}

void MainWindow::onFrameReady()
{
    const auto& out = m_doc->current();
    m_view->setOutput(out);
    refreshCellHighlights();
    if (m_hover && m_view->toolActive())
        refreshPreview();
    // The view first; the panels follow once it has painted (at once when it cannot paint).
    if (!m_view->isVisible())
        refreshPanels();
    if (out)
        m_status_time->setText(tr("core %1 ms · worker %2 ms")
                                   .arg(out->result.report.total_ms, 0, 'f', 3)
                                   .arg(out->worker_ms, 0, 'f', 2));
}

void MainWindow::refreshPreview()
{
    m_lut_panel->preview(m_view->toolActive() ? m_hover : std::nullopt);
}

void MainWindow::refreshCellHighlights()
{
    // The pixels of the current frame in the cells of a UV selection (cyan) and of the compare
    // dialog's chosen row (orange), found again for every frame shown.
    const auto& out = m_doc->current();
    const auto light = [&](const QString& id, const CellMask* cells, QColor colour) {
        m_view->setHighlight(id, cells && out && !out->frame.ycbcr.empty()
                                     ? maskToQImage(pixelsIn(out->frame.ycbcr, *cells), colour)
                                     : QImage());
    };
    const auto& selection = m_uv->canvas().selection();
    light(QStringLiteral("uv_selection"), selection ? &*selection : nullptr,
          QColor(0, 230, 255, 170));
    light(QStringLiteral("compare"), m_compare_cells ? &*m_compare_cells : nullptr,
          QColor(255, 140, 0, 170));
}

void MainWindow::refreshPanels()
{
    const auto& out = m_doc->current();
    if (out && m_detections->shownSerial() == out->serial)
        return; // a repaint of the same frame (hover, zoom)
    m_detections->showOutput(out.get());
    if (m_hover)
        m_inspector->inspect(out.get(), *m_hover);
}

void MainWindow::updateTitle()
{
    QString title = QStringLiteral("Fieldsight");
    if (m_doc->hasStream()) {
        title = QStringLiteral("%1 — %2[*] — Fieldsight")
                    .arg(QFileInfo(m_doc->streamSpec()).fileName(),
                         m_doc->lutPath().isEmpty() ? tr("unsaved LUT")
                                                    : QFileInfo(m_doc->lutPath()).fileName());
    }
    setWindowTitle(title);
    setWindowModified(m_lut_doc->modified());
}

void MainWindow::onLutLoaded()
{
    // Edits are never dropped silently: a table loaded under unsaved edits (an open finishing
    // after a recovery) gives way to the edited one.
    if (m_lut_doc->modified()) {
        m_doc->setEditedLut(m_lut_doc->version());
        m_doc->setLutPath(m_lut_doc->path());
    } else {
        m_lut_doc->reset(m_doc->lut(), m_doc->lutPath());
    }
    m_lut_doc->setStream(m_doc->streamSpec());
    if (m_effect->stream() != m_doc->streamSpec()) // its settings follow settingsChanged
        m_effect->setStream(m_doc->streamSpec(), m_lut_doc->version());
    updateTitle();
}

bool MainWindow::saveLut()
{
    if (m_lut_doc->path().isEmpty() || !m_lut_doc->path().endsWith(QLatin1String(".lut")))
        return saveLutAs();
    if (Status s = m_lut_doc->save(); !s) {
        showMessage(
            tr("The LUT was not saved (the edits are kept): %1").arg(qs(s.error().message)));
        return false;
    }
    showMessage(tr("Saved %1").arg(m_lut_doc->path()), false);
    return true;
}

bool MainWindow::saveLutAs(const QString& given)
{
    QString path = given;
    if (path.isEmpty()) {
        QString suggestion = m_lut_doc->path();
        if (suggestion.isEmpty() || !suggestion.endsWith(QLatin1String(".lut")))
            suggestion = QFileInfo(m_doc->streamSpec()).absolutePath() + "/venue.lut";
        path = QFileDialog::getSaveFileName(this, tr("Save LUT as"), suggestion,
                                            tr("Fieldsight LUT (*.lut)"));
        if (path.isEmpty())
            return false;
    }
    if (!path.endsWith(QLatin1String(".lut"), Qt::CaseInsensitive))
        path += QStringLiteral(".lut");
    if (Status s = m_lut_doc->saveAs(path); !s) {
        showMessage(
            tr("The LUT was not saved (the edits are kept): %1").arg(qs(s.error().message)));
        return false;
    }
    m_doc->setLutPath(path);
    updateTitle();
    showMessage(tr("Saved %1").arg(path), false);
    return true;
}

bool MainWindow::confirmLutChanges()
{
    if (!m_lut_doc->modified())
        return true;
    const auto answer = QMessageBox::question(
        this, tr("Unsaved LUT edits"), tr("The LUT has edits that are not saved. Save them first?"),
        QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
    if (answer == QMessageBox::Cancel)
        return false;
    if (answer == QMessageBox::Save)
        return saveLut();
    m_lut_doc->reset(m_doc->lut(), m_doc->lutPath()); // discarded: what loads next replaces it
    m_lut_doc->discardRecovery();
    return true;
}

void MainWindow::offerRecovery()
{
    const std::optional<LutRecovery> r = m_lut_doc->findRecovery();
    if (!r) {
        m_recovery_bar->hide();
        return;
    }
    m_recovery_label->setText(
        tr("Unsaved LUT edits from %1 (%2) were recovered after the last session ended. "
           "Recover them?")
            .arg(r->saved_at, r->path.isEmpty() ? tr("a new table") : r->path));
    m_recovery_bar->show();
}

bool MainWindow::recoverLut()
{
    const std::optional<LutRecovery> r = m_lut_doc->findRecovery();
    m_recovery_bar->hide();
    if (!r)
        return false;
    if (Status s = m_lut_doc->recover(*r); !s) {
        showMessage(qs(s.error().message));
        return false;
    }
    m_doc->setLutPath(m_lut_doc->path());
    updateTitle();
    showMessage(tr("Recovered the LUT edits; save them with Ctrl+S"), false);
    return true;
}

void MainWindow::rememberRecent(const QString& spec)
{
    const QString path =
        spec.startsWith(QLatin1String("camera:")) ? spec : QFileInfo(spec).absoluteFilePath();
    m_recent.removeAll(path);
    m_recent.prepend(path);
    while (m_recent.size() > kMaxRecent)
        m_recent.removeLast();
    rebuildRecentMenu();
}

void MainWindow::rebuildRecentMenu()
{
    m_recent_menu->clear();
    for (const QString& path : m_recent)
        m_recent_menu->addAction(path, this, [this, path] { openStream(path); });
    m_recent_menu->setEnabled(!m_recent.isEmpty());
}

void MainWindow::addBookmark()
{
    if (!m_doc->hasStream())
        return;
    const std::size_t frame = m_doc->currentIndex();
    const Bookmark* existing = m_doc->bookmarks().find(frame);
    bool ok = false;
    const QString note =
        QInputDialog::getText(this, tr("Bookmark frame %1").arg(frame), tr("Note:"),
                              QLineEdit::Normal, existing ? qs(existing->note) : QString(), &ok);
    if (!ok)
        return;
    if (Status s = m_doc->setBookmark(frame, note); !s)
        showMessage(qs(s.error().message));
}

void MainWindow::jumpBookmark(int direction)
{
    const auto& list = m_doc->bookmarks().list();
    const std::size_t now = m_doc->currentIndex();
    if (direction > 0) {
        for (const Bookmark& b : list)
            if (b.frame > now)
                return m_doc->setCurrentIndex(b.frame);
    } else {
        for (auto it = list.rbegin(); it != list.rend(); ++it)
            if (it->frame < now)
                return m_doc->setCurrentIndex(it->frame);
    }
}

void MainWindow::refreshBookmarks()
{
    m_bookmark_list->clear();
    for (const Bookmark& b : m_doc->bookmarks().list()) {
        auto* item = new QListWidgetItem(
            tr("%1  %2").arg(qulonglong(b.frame), 6).arg(qs(b.note.empty() ? b.name : b.note)),
            m_bookmark_list);
        item->setData(Qt::UserRole, qulonglong(b.frame));
        item->setToolTip(qs(b.name));
    }
}

QImage MainWindow::snapshot()
{
    return m_view->grab().toImage();
}

bool MainWindow::saveSnapshot(const QString& path)
{
    QByteArray png;
    QBuffer buffer(&png);
    buffer.open(QIODevice::WriteOnly);
    if (!snapshot().save(&buffer, "PNG")) {
        showMessage(tr("%1: cannot encode the view as PNG").arg(path));
        return false;
    }
    if (Status s = writeFileAtomically(toLocalPath(path), png.constData(), std::size_t(png.size()));
        !s) {
        showMessage(qs(s.error().message));
        return false;
    }
    showMessage(tr("Saved the view to %1").arg(path), false);
    return true;
}

void MainWindow::copySnapshot()
{
    QApplication::clipboard()->setImage(snapshot());
    statusBar()->showMessage(tr("The view is on the clipboard"), 4000);
}

void MainWindow::saveSettings() const
{
    QSettings s;
    s.setValue(QStringLiteral("window/geometry"), saveGeometry());
    s.setValue(QStringLiteral("window/state"), saveState());
    s.setValue(QStringLiteral("view/layers"), toList(m_view->visibleLayers()));
    s.setValue(QStringLiteral("view/mode"), int(m_view->mode()));
    s.setValue(QStringLiteral("view/labels"), m_labels_action->isChecked());
    s.setValue(QStringLiteral("play/fps"), m_navigator->speed());
    s.setValue(QStringLiteral("play/loop"), m_navigator->loopAction()->isChecked());
    QVariantList recent;
    for (const QString& path : m_recent)
        recent << pathSetting(path);
    s.setValue(QStringLiteral("recent/streams"), recent);
    if (m_doc->hasStream()) {
        s.setValue(QStringLiteral("session/stream"),
                   pathSetting(m_recent.value(0, m_doc->streamSpec())));
        s.setValue(QStringLiteral("session/lut"),
                   pathSetting(m_doc->lutPath().isEmpty()
                                   ? QString()
                                   : QFileInfo(m_doc->lutPath()).absoluteFilePath()));
    }
}

void MainWindow::restoreSettings()
{
    const QSettings s;
    if (!restoreGeometry(s.value(QStringLiteral("window/geometry")).toByteArray())) {
        // First run: 1280 x 800, or most of a smaller screen.
        QSize size(1280, 800);
        if (const QScreen* screen = QGuiApplication::primaryScreen())
            size = size.boundedTo(screen->availableSize() * 0.95);
        resize(size);
    }
    restoreState(s.value(QStringLiteral("window/state")).toByteArray());
    if (s.contains(QStringLiteral("view/layers"))) {
        LayerSet layers;
        for (const QString& id : s.value(QStringLiteral("view/layers")).toStringList())
            layers.insert(id.toStdString());
        m_layers->setVisibleLayers(layers);
    } else {
        m_layers->setVisibleLayers(LayersPanel::defaultLayers(m_doc->pipeline()));
    }
    setMode(ViewMode(std::clamp(s.value(QStringLiteral("view/mode"), 0).toInt(), 0, 3)));
    m_labels_action->setChecked(s.value(QStringLiteral("view/labels"), true).toBool());
    m_view->setLabelsShown(m_labels_action->isChecked());
    m_navigator->setSpeed(s.value(QStringLiteral("play/fps"), 30).toInt());
    m_navigator->loopAction()->setChecked(s.value(QStringLiteral("play/loop"), false).toBool());
    m_recent.clear();
    for (const QVariant& path : s.value(QStringLiteral("recent/streams")).toList())
        m_recent << pathFromSetting(path);
    rebuildRecentMenu();
}

void MainWindow::closeEvent(QCloseEvent* event)
{
    if (!confirmLutChanges()) {
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
    openPath(urls.front().toLocalFile());
    event->acceptProposedAction();
}

} // namespace fieldsight::ui
