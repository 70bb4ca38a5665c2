#include "ui/panels/evaluation_panel.h"

#include "ui/adapters/image_adapter.h"
#include "ui/adapters/overlay_painter.h"

#include <QFileInfo>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QListWidget>
#include <QPainter>
#include <QProgressBar>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace fieldsight::ui {

namespace {

/// The culprits' colours: a missed true object and a false detection, drawn wide under the
/// overlay so the kind's own drawing still shows on top.
constexpr Rgb kMissedColour{255, 40, 200};
constexpr Rgb kFalseColour{0, 230, 255};
constexpr Rgb kHaloRim{0, 0, 0};
constexpr double kHaloWidth = 5;

QString noun(const PerceptKind& kind)
{
    return perceptNoun(kind).toLower();
}

/// "0.91 → 0.97", with three decimals where two would read the same.
QString changeOf(double before, double after)
{
    int decimals = 2;
    if (QString::number(before, 'f', 2) == QString::number(after, 'f', 2))
        decimals = 3;
    return QStringLiteral("%1 → %2").arg(QString::number(before, 'f', decimals),
                                         QString::number(after, 'f', decimals));
}

QString describe(const FailingFrame& f)
{
    const FrameDisagreement& d = f.disagreement;
    QStringList parts;
    if (!d.missed.empty())
        parts << EvaluationPanel::tr("%1 missed").arg(d.missed.size());
    if (!d.false_detections.empty())
        parts << EvaluationPanel::tr("%1 false").arg(d.false_detections.size());
    return EvaluationPanel::tr("Frame %1 · %2: %3")
        .arg(f.index)
        .arg(perceptNoun(*d.kind), parts.join(QStringLiteral(", ")));
}

} // namespace

QString scoreChangeText(const EvaluationScores& before, const EvaluationScores& after)
{
    QStringList parts;
    for (const auto& [kind, a] : after.classes()) {
        const ClassScore* b = before.find(*kind);
        if (!b)
            continue;
        if (b->precision() != a.precision())
            parts << QStringLiteral("%1 %2 %3")
                         .arg(noun(*kind), EvaluationPanel::tr("precision"),
                              changeOf(b->precision(), a.precision()));
        if (b->recall() != a.recall())
            parts << QStringLiteral("%1 %2 %3")
                         .arg(noun(*kind), EvaluationPanel::tr("recall"),
                              changeOf(b->recall(), a.recall()));
    }
    const double eb = before.boundaryMeanError();
    const double ea = after.boundaryMeanError();
    if (eb >= 0 && ea >= 0 && eb != ea)
        parts << EvaluationPanel::tr("%1 error %2 px").arg(noun(boundaryKind()), changeOf(eb, ea));
    return parts.isEmpty() ? EvaluationPanel::tr("no change in the scores")
                           : parts.join(QStringLiteral(", "));
}

EvaluationPanel::EvaluationPanel(EvaluationScan& scan, StreamDocument& stream, QWidget* parent)
    : QWidget(parent), m_scan(scan), m_stream(stream)
{
    auto* column = new QVBoxLayout(this);
    column->setContentsMargins(2, 2, 2, 2);
    column->setSpacing(3);
    // What the last change did comes first: it is what an editor looks here for.
    m_change = new QLabel(this);
    m_change->setObjectName(QStringLiteral("evaluation.change"));
    m_change->setWordWrap(true);
    m_change->setTextInteractionFlags(Qt::TextSelectableByMouse);
    QFont bold = m_change->font();
    bold.setBold(true);
    m_change->setFont(bold);
    column->addWidget(m_change);

    auto* row = new QHBoxLayout;
    m_status = new QLabel(this);
    m_status->setObjectName(QStringLiteral("evaluation.status"));
    m_status->setWordWrap(true);
    m_run = new QPushButton(tr("Evaluate"), this);
    m_run->setObjectName(QStringLiteral("evaluation.run"));
    m_run->setToolTip(tr("Run the pipeline over every annotated frame and score it (as "
                         "fieldsight eval does)"));
    m_cancel = new QPushButton(tr("Cancel"), this);
    m_cancel->setObjectName(QStringLiteral("evaluation.cancel"));
    connect(m_run, &QPushButton::clicked, &m_scan, &EvaluationScan::evaluate);
    connect(m_cancel, &QPushButton::clicked, &m_scan, &EvaluationScan::cancel);
    row->addWidget(m_status, 1);
    row->addWidget(m_run, 0, Qt::AlignTop);
    row->addWidget(m_cancel, 0, Qt::AlignTop);
    column->addLayout(row);
    m_progress = new QProgressBar(this);
    m_progress->setObjectName(QStringLiteral("evaluation.progress"));
    m_progress->setTextVisible(true);
    column->addWidget(m_progress);

    m_scores = new QTableWidget(this);
    m_scores->setObjectName(QStringLiteral("evaluation.scores"));
    m_scores->setColumnCount(7);
    // Short headers (their tooltips say the rest) and compact rows: the table fits the dock's
    // default width at 1280x800 with no scroll bar hiding a row or a column.
    m_scores->setHorizontalHeaderLabels(
        {tr("Class"), tr("TP"), tr("FP"), tr("FN"), tr("Prec."), tr("Rec."), tr("Conc.")});
    m_scores->horizontalHeaderItem(1)->setToolTip(
        tr("True positives: detections of a true object"));
    m_scores->horizontalHeaderItem(2)->setToolTip(
        tr("False positives: detections no true object matches"));
    m_scores->horizontalHeaderItem(3)->setToolTip(
        tr("False negatives: true objects no detection matches"));
    m_scores->horizontalHeaderItem(4)->setToolTip(tr("Precision: TP / (TP + FP)"));
    m_scores->horizontalHeaderItem(5)->setToolTip(tr("Recall: TP / (TP + FN)"));
    m_scores->horizontalHeaderItem(6)->setToolTip(
        tr("Concealed true objects found / missed: counted in neither TP, FP nor FN"));
    m_scores->verticalHeader()->hide();
    m_scores->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_scores->setSelectionMode(QAbstractItemView::NoSelection);
    m_scores->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    // The class names take the room left over, so the table spans the dock.
    m_scores->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
    m_scores->horizontalHeader()->setMinimumSectionSize(fontMetrics().horizontalAdvance('0') * 2);
    QFont compact = m_scores->font();
    compact.setPointSizeF(compact.pointSizeF() * 0.9);
    m_scores->setFont(compact);
    m_scores->horizontalHeader()->setFont(compact);
    m_scores->verticalHeader()->setSectionResizeMode(QHeaderView::Fixed);
    m_scores->verticalHeader()->setDefaultSectionSize(QFontMetrics(compact).height() + 4);
    m_scores->setWordWrap(false);
    m_scores->setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    m_scores->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    m_kinds = scoredKinds(m_scan.pipeline().perceptKinds());
    m_scores->setRowCount(int(m_kinds.size()));
    for (int r = 0; r < m_scores->rowCount(); ++r) {
        const std::string_view title = m_kinds[std::size_t(r)]->title;
        m_scores->setItem(
            r, 0, new QTableWidgetItem(QString::fromUtf8(title.data(), qsizetype(title.size()))));
    }
    int height = m_scores->horizontalHeader()->sizeHint().height() + 2 * m_scores->frameWidth();
    for (int r = 0; r < m_scores->rowCount(); ++r)
        height += m_scores->rowHeight(r);
    m_scores->setFixedHeight(height);
    column->addWidget(m_scores);

    m_boundary = new QLabel(this);
    m_boundary->setObjectName(QStringLiteral("evaluation.boundary"));
    m_boundary->setWordWrap(true);
    column->addWidget(m_boundary);

    auto* failing_title =
        new QLabel(tr("Frames where detections and truth disagree (F6: next):"), this);
    failing_title->setWordWrap(true);
    column->addWidget(failing_title);
    m_frames = new QListWidget(this);
    m_frames->setObjectName(QStringLiteral("evaluation.frames"));
    m_frames->setToolTip(tr("Choose one to go there: a missed true object is drawn pink, a "
                            "false detection cyan"));
    connect(m_frames, &QListWidget::itemActivated, this,
            [this](QListWidgetItem* item) { showDisagreement(m_frames->row(item)); });
    connect(m_frames, &QListWidget::itemClicked, this,
            [this](QListWidgetItem* item) { showDisagreement(m_frames->row(item)); });
    column->addWidget(m_frames, 1);

    connect(&m_scan, &EvaluationScan::started, this, &EvaluationPanel::refreshProgress);
    connect(&m_scan, &EvaluationScan::progressed, this, &EvaluationPanel::refreshProgress);
    connect(&m_scan, &EvaluationScan::finished, this, &EvaluationPanel::refresh);
    // Another frame shown: the culprits drawn belong to the frame chosen only.
    connect(&m_stream, &StreamDocument::currentIndexChanged, this, [this](std::size_t index) {
        const auto& failing = m_scan.failing();
        if (m_chosen >= 0 && (std::size_t(m_chosen) >= failing.size() ||
                              failing[std::size_t(m_chosen)].index != index)) {
            m_chosen = -1;
            m_frames->clearSelection();
            emit highlightChanged(QImage());
        }
    });
    refresh();
}

QString EvaluationPanel::changeText() const
{
    const EvalReport* report = m_scan.report();
    const EvaluationScores* before = m_scan.before();
    return report && before ? scoreChangeText(*before, report->scores) : QString();
}

QString EvaluationPanel::statusText() const
{
    return m_status->text();
}

void EvaluationPanel::refreshProgress()
{
    const bool running = m_scan.running();
    m_progress->setVisible(running);
    m_cancel->setVisible(running);
    m_run->setVisible(!running);
    if (!running)
        return;
    const auto [done, total] = m_scan.progress();
    m_progress->setRange(0, int(std::max<std::size_t>(total, 1)));
    m_progress->setValue(int(done));
    m_progress->setFormat(tr("%1 of %2 annotated frames").arg(done).arg(total));
    m_status->setText(m_scan.report() ? tr("Scoring again after the change…")
                                      : tr("Evaluating the annotated frames…"));
}

void EvaluationPanel::refresh()
{
    refreshProgress();
    const EvalReport* report = m_scan.report();
    const auto& failing = m_scan.failing();
    if (!m_scan.running()) {
        if (!m_scan.problem().isEmpty())
            m_status->setText(m_scan.problem());
        else if (!report)
            m_status->setText(m_stream.hasStream() && m_scan.stream().isEmpty()
                                  ? tr("A live camera has no annotations to score")
                                  : tr("No evaluation yet"));
        else {
            const EvaluationScores& s = report->scores;
            QString text = tr("%1 done frames scored against %2")
                               .arg(s.frames)
                               .arg(QFileInfo(m_scan.truthPath()).fileName());
            if (s.frames_reviewed)
                text += tr(", %1 more for their reviewed kinds").arg(s.frames_reviewed);
            text += failing.size() == 1 ? tr("; 1 disagreement")
                                        : tr("; %1 disagreements").arg(failing.size());
            if (m_scan.lastRunMs() >= 0)
                text += tr(" (%1 s)").arg(m_scan.lastRunMs() / 1000.0, 0, 'f', 2);
            m_status->setText(text);
        }
    }
    const auto classes = report ? report->scores.classes()
                                : std::vector<std::pair<const PerceptKind*, ClassScore>>();
    // The concealed column only when some true object is concealed.
    m_scores->setColumnHidden(6, std::none_of(classes.begin(), classes.end(), [](const auto& c) {
                                  return c.second.concealed_found + c.second.concealed_missed > 0;
                              }));
    for (int r = 0; r < m_scores->rowCount(); ++r) {
        const ClassScore* score = report ? report->scores.find(*m_kinds[std::size_t(r)]) : nullptr;
        const bool known = score != nullptr;
        const ClassScore c = known ? *score : ClassScore{};
        const QString dash = QStringLiteral("–");
        const QStringList cells{known ? QString::number(c.tp) : dash,
                                known ? QString::number(c.fp) : dash,
                                known ? QString::number(c.fn) : dash,
                                known ? QString::number(c.precision(), 'f', 3) : dash,
                                known ? QString::number(c.recall(), 'f', 3) : dash,
                                known && c.concealed_found + c.concealed_missed > 0
                                    ? tr("%1 / %2").arg(c.concealed_found).arg(c.concealed_missed)
                                    : dash};
        for (int col = 0; col < cells.size(); ++col) {
            auto* item = new QTableWidgetItem(cells[col]);
            item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
            m_scores->setItem(r, col + 1, item);
        }
    }
    const QString boundary = perceptNoun(boundaryKind());
    if (report && report->scores.boundary_frames > 0)
        m_boundary->setText(
            tr("%1: mean error %2 px over %3 %4")
                .arg(boundary)
                .arg(report->scores.boundaryMeanError(), 0, 'f', 2)
                .arg(report->scores.boundary_frames)
                .arg(report->scores.boundary_frames == 1 ? tr("frame") : tr("frames")));
    else
        m_boundary->setText(tr("%1: no frame with both a detected and a true one").arg(boundary));
    const QString change = changeText();
    m_change->setVisible(!change.isEmpty());
    m_change->setText(tr("Last change: %1").arg(change));

    m_frames->clear();
    for (const FailingFrame& f : failing) {
        auto* item = new QListWidgetItem(describe(f), m_frames);
        item->setToolTip(QString::fromStdString(f.disagreement.frame));
    }
    // The disagreement chosen before, found again (its culprits may have moved).
    const int previous = m_chosen;
    m_chosen = -1;
    if (previous >= 0) {
        for (std::size_t i = 0; i < failing.size(); ++i)
            if (failing[i].index == m_chosen_what.index &&
                failing[i].disagreement.kind == m_chosen_what.disagreement.kind &&
                failing[i].index == m_stream.currentIndex()) {
                choose(int(i));
                break;
            }
        if (m_chosen < 0)
            emit highlightChanged(QImage());
    }
    emit marksChanged();
}

std::map<std::size_t, QString> EvaluationPanel::frameMarks() const
{
    std::map<std::size_t, QString> marks;
    for (const FailingFrame& f : m_scan.failing()) {
        QString& line = marks[f.index];
        line = line.isEmpty() ? describe(f) : line + QStringLiteral("; ") + describe(f);
    }
    return marks;
}

void EvaluationPanel::choose(int row)
{
    const auto& failing = m_scan.failing();
    if (row < 0 || std::size_t(row) >= failing.size())
        return;
    m_chosen = row;
    m_chosen_what = failing[std::size_t(row)];
    m_frames->setCurrentRow(row);
    m_frames->scrollToItem(m_frames->item(row));
    const QImage image = culpritImage(m_chosen_what);
    emit highlightChanged(image);
    // Where the culprits are (image px), so the view can bring them into sight.
    QRect bounds;
    for (int y = 0; y < image.height(); ++y) {
        const auto* pixels = reinterpret_cast<const QRgb*>(image.constScanLine(y));
        for (int x = 0; x < image.width(); ++x)
            if (qAlpha(pixels[x]) != 0)
                bounds |= QRect(x, y, 1, 1);
    }
    if (!bounds.isEmpty())
        emit culpritsAt(bounds);
}

void EvaluationPanel::showDisagreement(int row)
{
    const auto& failing = m_scan.failing();
    if (row < 0 || std::size_t(row) >= failing.size())
        return;
    // Chosen first: the frame change that follows keeps it.
    choose(row);
    m_stream.setCurrentIndex(failing[std::size_t(row)].index);
}

void EvaluationPanel::showFrame(std::size_t index)
{
    const auto& failing = m_scan.failing();
    for (std::size_t i = 0; i < failing.size(); ++i)
        if (failing[i].index == index)
            return showDisagreement(int(i));
    m_stream.setCurrentIndex(index);
}

void EvaluationPanel::jump(int direction)
{
    const auto& failing = m_scan.failing();
    if (failing.empty())
        return;
    const std::size_t now = m_stream.currentIndex();
    int row = -1;
    if (m_chosen >= 0) {
        row = m_chosen + (direction > 0 ? 1 : -1);
    } else if (direction > 0) {
        for (std::size_t i = 0; i < failing.size() && row < 0; ++i)
            if (failing[i].index > now)
                row = int(i);
    } else {
        for (std::size_t i = failing.size(); i-- > 0 && row < 0;)
            if (failing[i].index < now)
                row = int(i);
    }
    if (row >= 0 && std::size_t(row) < failing.size())
        showDisagreement(row);
}

QImage EvaluationPanel::culpritImage(const FailingFrame& failing) const
{
    const EvalReport* report = m_scan.report();
    const auto& truth = m_scan.truth();
    const FrameDisagreement& d = failing.disagreement;
    if (!report || !truth || !m_stream.hasStream())
        return {};
    const StreamInfo& info = m_stream.info();
    QImage image(info.width, info.height, QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::transparent);
    DebugDrawing drawing;
    // The chosen objects of one list, through the kind's own drawing, wide and bright.
    const auto add = [&](const PerceptEntry* list, const std::vector<std::size_t>& indices,
                         Rgb colour) {
        if (!list)
            return;
        const std::vector<EditShape> shapes = list->shapes();
        std::vector<EditShape> chosen;
        for (std::size_t i : indices)
            if (i < shapes.size())
                chosen.push_back(shapes[i]);
        const std::unique_ptr<PerceptEntry> copy = d.kind->make();
        copy->setShapes(chosen);
        copy->draw(kHaloRim, kHaloWidth + 2, drawing);
        copy->draw(colour, kHaloWidth, drawing);
    };
    if (const auto t = truth->frames.find(d.frame); t != truth->frames.end())
        add(t->second.truth.find(*d.kind), d.missed, kMissedColour);
    if (const auto s = m_scan.detected().find(d.frame); s != m_scan.detected().end())
        add(s->second.find(*d.kind), d.false_detections, kFalseColour);
    QPainter painter(&image);
    paintDrawing(painter, drawing);
    return image;
}

} // namespace fieldsight::ui
