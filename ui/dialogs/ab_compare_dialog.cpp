// Compare A/B in the window: choosing side B, the background run, the list of changed frames.
#include "ui/dialogs/ab_compare_dialog.h"

#include "ui/adapters/local_path.h"
#include "ui/dialogs/dialogs.h"
#include "visioncore/io/lut_import.h"

#include <QDialogButtonBox>
#include <QFileInfo>
#include <QGridLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QProgressBar>
#include <QPushButton>
#include <QTimer>
#include <QTreeWidget>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>

#include <chrono>

namespace fieldsight::ui {

namespace {

QString qs(const std::string& s)
{
    return QString::fromStdString(s);
}

/// "FP 1, FN 0" of one frame's score.
QString errors(const ClassScore& s)
{
    return QObject::tr("TP %1, FP %2, FN %3").arg(s.tp).arg(s.fp).arg(s.fn);
}

QString ratio(double v)
{
    return QString::number(v, 'f', 3);
}

constexpr int kIndexRole = Qt::UserRole;

} // namespace

AbCompareDialog::AbCompareDialog(EditingSession& session, QWidget* parent)
    : QDialog(parent), m_session(session)
{
    setObjectName(QStringLiteral("ab_compare"));
    setWindowTitle(tr("Compare A/B"));
    auto* column = new QVBoxLayout(this);

    m_sides = new QLabel(this);
    m_sides->setObjectName(QStringLiteral("ab.sides"));
    m_sides->setWordWrap(true);
    column->addWidget(m_sides);
    auto* choose = new QHBoxLayout;
    auto* table = new QPushButton(tr("Table B…"), this);
    table->setObjectName(QStringLiteral("ab.table"));
    connect(table, &QPushButton::clicked, this, &AbCompareDialog::chooseTable);
    auto* params = new QPushButton(tr("Parameters B…"), this);
    params->setObjectName(QStringLiteral("ab.params"));
    connect(params, &QPushButton::clicked, this, &AbCompareDialog::chooseParams);
    auto* same = new QPushButton(tr("B as A"), this);
    same->setToolTip(tr("Side B uses side A's table and parameters again"));
    connect(same, &QPushButton::clicked, this, [this] {
        m_table.reset();
        m_table_path.clear();
        m_params.reset();
        m_params_path.clear();
        refreshSides();
    });
    choose->addWidget(table);
    choose->addWidget(params);
    choose->addWidget(same);
    choose->addStretch();
    column->addLayout(choose);

    auto* run = new QHBoxLayout;
    m_start = new QPushButton(tr("Compare"), this);
    m_start->setObjectName(QStringLiteral("ab.start"));
    connect(m_start, &QPushButton::clicked, this, [this] { start(); });
    m_cancel_button = new QPushButton(tr("Cancel"), this);
    m_cancel_button->setObjectName(QStringLiteral("ab.cancel"));
    m_cancel_button->setEnabled(false);
    connect(m_cancel_button, &QPushButton::clicked, this, &AbCompareDialog::cancel);
    m_progress = new QProgressBar(this);
    m_progress->setObjectName(QStringLiteral("ab.progress"));
    m_progress->setRange(0, 1);
    m_progress->setValue(0);
    run->addWidget(m_start);
    run->addWidget(m_cancel_button);
    run->addWidget(m_progress, 1);
    column->addLayout(run);
    m_status = new QLabel(this);
    m_status->setObjectName(QStringLiteral("ab.status"));
    m_status->setWordWrap(true);
    column->addWidget(m_status);

    m_tree = new QTreeWidget(this);
    m_tree->setObjectName(QStringLiteral("ab.frames"));
    m_tree->setColumnCount(3);
    m_tree->setHeaderLabels({tr("Class / frame"), tr("A"), tr("B")});
    m_tree->header()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_tree->setToolTip(tr("Fixed: fewer misses and false detections with B than with A. Broken: "
                          "more. Choose a frame to show it."));
    connect(m_tree, &QTreeWidget::currentItemChanged, this, [this](QTreeWidgetItem* item) {
        if (!item || !item->data(0, kIndexRole).isValid())
            return;
        m_session.stream().setCurrentIndex(std::size_t(item->data(0, kIndexRole).toULongLong()));
    });
    column->addWidget(m_tree, 1);

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    column->addWidget(buttons);

    m_poll = new QTimer(this);
    m_poll->setInterval(100);
    connect(m_poll, &QTimer::timeout, this, [this] {
        m_progress->setRange(0, int(std::max<std::size_t>(1, m_total)));
        m_progress->setValue(int(m_done));
    });
    connect(&m_watcher, &QFutureWatcher<Outcome>::finished, this, &AbCompareDialog::onFinished);
    connect(&m_session.stream(), &StreamDocument::streamChanged, this, [this] {
        cancel();
        m_result.reset();
        m_tree->clear();
        refreshSides();
    });
    refreshSides();
    resize(560, 600);
}

AbCompareDialog::~AbCompareDialog()
{
    m_cancel = true;
    m_watcher.waitForFinished();
}

Status AbCompareDialog::setTableB(const QString& path)
{
    auto lut = importLut(toLocalPath(path));
    if (!lut)
        return lut.error();
    m_table = std::make_shared<const ColourLut>(std::move(lut).value());
    m_table_path = path;
    refreshSides();
    return {};
}

Status AbCompareDialog::setParamsB(const QString& path)
{
    auto params = ParamSet::load(toLocalPath(path));
    if (!params)
        return params.error();
    if (Status s = params.value().check(m_session.pipeline()); !s)
        return Error{toLocalPath(path) + ": " + s.error().message};
    m_params = std::move(params).value();
    m_params_path = path;
    refreshSides();
    return {};
}

void AbCompareDialog::chooseTable()
{
    const QString path = Dialogs::current().openFile(
        this, tr("Table B"), QFileInfo(m_session.lut().path()).path(), tr("Colour tables (*)"));
    if (path.isEmpty())
        return;
    if (Status s = setTableB(path); !s)
        m_status->setText(qs(s.error().message));
}

void AbCompareDialog::chooseParams()
{
    const QString path =
        Dialogs::current().openFile(this, tr("Parameters B"), {}, tr("Parameter sets (*.json)"));
    if (path.isEmpty())
        return;
    if (Status s = setParamsB(path); !s)
        m_status->setText(qs(s.error().message));
}

void AbCompareDialog::refreshSides()
{
    const QString a_table =
        m_session.lut().path().isEmpty()
            ? tr("the table being edited")
            : tr("the table being edited (%1)").arg(QFileInfo(m_session.lut().path()).fileName());
    const QString b_table = m_table ? QFileInfo(m_table_path).fileName() : tr("A's table");
    const QString b_params = m_params ? QFileInfo(m_params_path).fileName() : tr("A's parameters");
    m_sides->setText(tr("A: %1 with the pipeline's parameters.\nB: %2 with %3.\nOver the annotated "
                        "frames of %4 (each class where its truth is complete).")
                         .arg(a_table, b_table, b_params,
                              m_session.stream().hasStream() ? m_session.stream().streamSpec()
                                                             : tr("no stream")));
    m_start->setEnabled(!running() && (m_table || m_params));
}

bool AbCompareDialog::start()
{
    StreamDocument& stream = m_session.stream();
    const auto refuse = [this](const QString& why) {
        m_status->setText(why);
        emit comparisonEnded();
        return false;
    };
    if (running())
        return false;
    if (!m_table && !m_params)
        return refuse(tr("Choose table B or parameters B first."));
    if (!stream.hasStream() || stream.live())
        return refuse(tr("Open a stream with annotations first."));
    // The annotations as the document holds them, unsaved edits too.
    const AnnotationsDocument& annotations = m_session.annotations();
    if (!annotations.loadProblem().isEmpty())
        return refuse(annotations.loadProblem());
    const std::string spec = toLocalPath(stream.streamSpec());
    const std::string truth_path = toLocalPath(annotations.path());
    Annotations truth = annotations.annotations();
    StreamOptions options;
    options.orientation = stream.orientation();
    auto reader = openStream(spec, options);
    if (!reader)
        return refuse(qs(reader.error().message));

    auto input = std::make_shared<StreamInput>();
    input->stream = spec;
    input->reader = std::move(reader).value();
    input->lut_path = toLocalPath(m_session.lut().path());
    input->lut = m_session.lut().version();
    input->pipeline = &m_session.pipeline();
    input->params = m_session.settings().paramChanges();
    const StageSet& skipped = m_session.settings().skippedStages();
    input->skip.assign(skipped.begin(), skipped.end());
    AbSide b;
    b.lut = m_table;
    b.lut_path = toLocalPath(m_table_path);
    b.params = m_params.value_or(input->params);
    b.params_path = toLocalPath(m_params_path);

    m_result.reset();
    m_tree->clear();
    m_cancel = false;
    m_done = 0;
    m_total = 0;
    m_start->setEnabled(false);
    m_cancel_button->setEnabled(true);
    m_status->setText(tr("Comparing…"));
    m_poll->start();
    m_watcher.setFuture(
        QtConcurrent::run([this, input, b = std::move(b), truth = std::move(truth), truth_path]() {
            RunHooks hooks;
            hooks.cancel = &m_cancel;
            hooks.progress = [this](std::size_t done, std::size_t total) {
                m_total = total;
                m_done = done;
            };
            const auto started = std::chrono::steady_clock::now();
            Outcome out{compareAb(*input, b, truth, truth_path, 0, hooks), 0};
            out.seconds =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
            return out;
        }));
    return true;
}

void AbCompareDialog::cancel()
{
    m_cancel = true;
}

QString AbCompareDialog::status() const
{
    return m_status->text();
}

void AbCompareDialog::onFinished()
{
    m_poll->stop();
    m_cancel_button->setEnabled(false);
    const Outcome out = m_watcher.result();
    if (!out.comparison) {
        m_status->setText(qs(out.comparison.error().message));
    } else if (out.comparison.value().cancelled) {
        m_status->setText(tr("Cancelled."));
    } else if (out.comparison.value().frames == 0) {
        m_status->setText(tr("Nothing to compare: no frame of the annotations is done or has a "
                             "reviewed class."));
    } else {
        m_result = out.comparison.value();
        fill(*m_result);
        m_progress->setValue(m_progress->maximum());
        m_status->setText(tr("%1 annotated frames compared in %2 s.")
                              .arg(m_result->frames)
                              .arg(out.seconds, 0, 'f', 1));
    }
    refreshSides();
    emit comparisonEnded();
}

void AbCompareDialog::fill(const AbComparison& c)
{
    m_tree->clear();
    for (const AbClass& k : c.classes) {
        auto* top = new QTreeWidgetItem(m_tree);
        top->setText(0, tr("%1: %2 fixed, %3 broken (%4 frames)")
                            .arg(qs(k.name))
                            .arg(k.fixed.size())
                            .arg(k.broken.size())
                            .arg(k.frames));
        top->setText(1, tr("P %1, R %2").arg(ratio(k.a.precision()), ratio(k.a.recall())));
        top->setText(2, tr("P %1, R %2").arg(ratio(k.b.precision()), ratio(k.b.recall())));
        top->setData(0, Qt::UserRole + 1, qs(k.name));
        for (const auto& [label, list] :
             {std::pair{tr("fixed"), &k.fixed}, std::pair{tr("broken"), &k.broken}}) {
            for (const AbFrame& f : *list) {
                auto* item = new QTreeWidgetItem(top);
                item->setText(0, tr("%1 %2").arg(label, qs(f.name)));
                item->setText(1, errors(f.a));
                item->setText(2, errors(f.b));
                item->setData(0, kIndexRole, qulonglong(f.index));
            }
        }
        top->setExpanded(true);
    }
}

} // namespace fieldsight::ui
