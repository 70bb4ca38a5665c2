#include "ui/panels/fit_result_dialog.h"

#include <QDialogButtonBox>
#include <QGuiApplication>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QScreen>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace fieldsight::ui {

namespace {

QString qs(std::string_view s)
{
    return QString::fromUtf8(s.data(), qsizetype(s.size()));
}

int decimalsFor(double step)
{
    if (step <= 0)
        return 3;
    return std::clamp(int(std::ceil(-std::log10(step) - 1e-9)), 0, 6);
}

/// "1 frame", "20 frames".
QString count(std::size_t n, const QString& one, const QString& many)
{
    return n == 1 ? one : many.arg(QLocale().toString(qulonglong(n)));
}

QString ratio(double v)
{
    return QString::number(v, 'f', 2);
}

/// "+0.021", "−0.004", "0.000".
QString signedScore(double v)
{
    if (std::abs(v) < 0.0005)
        return QStringLiteral("0.000");
    return (v > 0 ? QStringLiteral("+") : QStringLiteral("−")) +
           QString::number(std::abs(v), 'f', 3);
}

/// A term's title: its kind's (of `kinds`, the pipeline's scored kinds), else the name itself.
QString termTitle(const std::string& term, const std::vector<const PerceptKind*>& kinds)
{
    if (term == kBoundaryTerm)
        return qs(boundaryKind().title);
    for (const PerceptKind* kind : kinds)
        if (scoredClassName(*kind) == term)
            return qs(kind->title);
    return QString::fromStdString(term);
}

const QColor kBetter(0, 120, 0);
const QColor kWorse(180, 0, 0);

enum Column { kClass, kFitStart, kFitTuned, kHeldStart, kHeldTuned, kColumns };

QTableWidget* makeTable(QWidget* parent, const QString& name, const QStringList& headers)
{
    auto* table = new QTableWidget(0, int(headers.size()), parent);
    table->setObjectName(name);
    table->setHorizontalHeaderLabels(headers);
    table->verticalHeader()->hide();
    table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    // A report to read: no cell to choose, no focus frame on one.
    table->setSelectionMode(QAbstractItemView::NoSelection);
    table->setFocusPolicy(Qt::NoFocus);
    table->setWordWrap(false);
    table->horizontalHeader()->setDefaultAlignment(Qt::AlignLeft | Qt::AlignVCenter);
    table->verticalHeader()->setSectionResizeMode(QHeaderView::Fixed);
    table->verticalHeader()->setDefaultSectionSize(table->fontMetrics().height() + 8);
    return table;
}

QTableWidgetItem* item(const QString& text, Qt::Alignment align = Qt::AlignLeft)
{
    auto* it = new QTableWidgetItem(text);
    it->setTextAlignment(align | Qt::AlignVCenter);
    return it;
}

/// Colours a tuned cell by whether it is better than the start (`sign` 1: higher is better).
void mark(QTableWidgetItem* tuned, double start, double after, int sign)
{
    const double d = (after - start) * sign;
    if (std::abs(d) < 0.0005) // not seen in the numbers shown
        return;
    tuned->setForeground(d > 0 ? kBetter : kWorse);
}

} // namespace

QString paramValueText(const ParamInfo& param, double value)
{
    QString text;
    switch (param.kind) {
    case ParamKind::Boolean:
        return value != 0 ? FitResultDialog::tr("on") : FitResultDialog::tr("off");
    case ParamKind::Choice:
        for (const ParamChoice& c : param.choices)
            if (c.value == int(std::lround(value)))
                return QString::fromStdString(c.name);
        return QString::number(std::lround(value));
    case ParamKind::Integer:
        text = QString::number(std::lround(value));
        break;
    case ParamKind::Real:
        text = QString::number(value, 'f', decimalsFor(param.step));
        break;
    }
    return param.unit.empty() ? text : text + ' ' + QString::fromStdString(param.unit);
}

FitResultDialog::FitResultDialog(TuneResult result, const Pipeline& pipeline, QWidget* parent)
    : QDialog(parent), m_result(std::move(result))
{
    setObjectName(QStringLiteral("fit_result"));
    setWindowTitle(tr("Fit to annotations"));
    auto* column = new QVBoxLayout(this);

    m_summary = new QLabel(this);
    m_summary->setObjectName(QStringLiteral("fit.summary"));
    m_summary->setWordWrap(true);
    m_summary->setTextInteractionFlags(Qt::TextSelectableByMouse);
    column->addWidget(m_summary);

    m_scores = makeTable(this, QStringLiteral("fit.scores"), {});
    column->addWidget(m_scores);
    auto* legend = new QLabel(tr("Each class: F1 (precision / recall); the field boundary: its "
                                 "median error; in green what the tuned parameters do better "
                                 "than the start, in red worse."),
                              this);
    legend->setWordWrap(true);
    column->addWidget(legend);
    auto* changes_title = new QLabel(tr("Parameters changed (what each bought: the fit score "
                                        "lost when it alone is put back):"),
                                     this);
    changes_title->setWordWrap(true);
    column->addWidget(changes_title);
    m_changes = makeTable(this, QStringLiteral("fit.changes"),
                          {tr("Parameter"), tr("Start"), tr("Tuned"), tr("Bought"),
                           tr("Per class, on the fit frames")});
    column->addWidget(m_changes, 1);

    m_note = new QLabel(this);
    m_note->setObjectName(QStringLiteral("fit.note"));
    m_note->setWordWrap(true);
    m_note->hide();
    column->addWidget(m_note);
    auto* how = new QLabel(tr("Apply puts the tuned parameters in use as one step of the pipeline "
                              "settings (Ctrl+Z takes them all back); Pipeline > Save parameters "
                              "to the stream then writes them to its params.json."),
                           this);
    how->setWordWrap(true);
    column->addWidget(how);

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Apply | QDialogButtonBox::Close, this);
    m_apply = buttons->button(QDialogButtonBox::Apply);
    m_apply->setObjectName(QStringLiteral("fit.apply"));
    m_apply->setEnabled(!m_result.changes.empty());
    connect(m_apply, &QPushButton::clicked, this, [this] {
        emit applyRequested();
        accept();
    });
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    column->addWidget(buttons);

    fillScores(pipeline);
    fillChanges(pipeline);

    const TuneResult& r = m_result;
    QStringList lines;
    if (r.cancelled)
        lines << tr("Cancelled after %1: these are the best parameters found so far.")
                     .arg(count(std::size_t(std::max(0, r.evaluations)), tr("1 evaluation"),
                                tr("%1 evaluations")));
    lines << tr("Fitted on %1")
                     .arg(count(r.fit_frames.size(), tr("1 annotated frame"),
                                tr("%1 annotated frames"))) +
                 (r.holdout_frames.empty()
                      ? tr(", none held out.")
                      : tr(", scored also on %1 the search did not fit.")
                            .arg(count(r.holdout_frames.size(), tr("1 held-out frame"),
                                       tr("%1 held-out frames"))));
    lines << tr("%1 evaluations of %2 parameters in %3 s.")
                 .arg(QLocale().toString(r.evaluations), QLocale().toString(r.parameters),
                      QLocale().toString(r.seconds, 'f', 1));
    QString totals = tr("Score on the fit frames %1 → %2")
                         .arg(QString::number(r.start_fit.total, 'f', 3),
                              QString::number(r.tuned_fit.total, 'f', 3));
    if (!r.holdout_frames.empty())
        totals += tr(", on the held-out frames %1 → %2")
                      .arg(QString::number(r.start_holdout.total, 'f', 3),
                           QString::number(r.tuned_holdout.total, 'f', 3));
    lines << totals + '.';
    if (r.changes.empty())
        lines << tr("No change scored better than the parameters in use: nothing to apply.");
    else if (!r.holdout_frames.empty() && r.tuned_holdout.total < r.start_holdout.total)
        lines << tr("The held-out frames score lower with the tuned parameters: the fit may not "
                    "hold on frames it did not see (annotate more frames, or a larger budget).");
    m_summary->setText(lines.join('\n'));
    fitSize();
}

QString FitResultDialog::summary() const
{
    return m_summary->text();
}

void FitResultDialog::setNote(const QString& note)
{
    m_note->setText(note);
    m_note->setVisible(!note.isEmpty());
}

void FitResultDialog::fillScores(const Pipeline& pipeline)
{
    const TuneResult& r = m_result;
    const QString fit = tr("Fit frames (%1)").arg(r.fit_frames.size());
    const QString held = tr("Held out (%1)").arg(r.holdout_frames.size());
    m_scores->setColumnCount(kColumns);
    m_scores->setHorizontalHeaderLabels({tr("Class"), fit + '\n' + tr("start"),
                                         fit + '\n' + tr("tuned"), held + '\n' + tr("start"),
                                         held + '\n' + tr("tuned")});
    for (int c = kFitStart; c < kColumns; ++c)
        m_scores->horizontalHeaderItem(c)->setToolTip(
            tr("F1 (precision / recall) of each class; the field boundary's median error; the "
               "weighted score the search maximises"));
    const TuneScore* by_column[kColumns] = {nullptr, &r.start_fit, &r.tuned_fit, &r.start_holdout,
                                            &r.tuned_holdout};
    const bool held_scored = !r.holdout_frames.empty();
    const auto add_row = [this](const QString& title) {
        const int row = m_scores->rowCount();
        m_scores->insertRow(row);
        m_scores->setItem(row, kClass, item(title));
        return row;
    };
    for (const PerceptKind* kind : scoredKinds(pipeline.perceptKinds())) {
        const std::string name = scoredClassName(*kind);
        if (std::none_of(by_column + 1, by_column + kColumns,
                         [&name](const TuneScore* s) { return s->classes.count(name) != 0; }))
            continue;
        const int row = add_row(qs(kind->title));
        for (int c = kFitStart; c < kColumns; ++c) {
            const auto it = by_column[c]->classes.find(name);
            const bool shown = it != by_column[c]->classes.end() &&
                               (held_scored || c == kFitStart || c == kFitTuned);
            auto* cell =
                item(shown ? QStringLiteral("%1  (%2 / %3)")
                                 .arg(ratio(f1Score(it->second)), ratio(it->second.precision()),
                                      ratio(it->second.recall()))
                           : QStringLiteral("—"),
                     Qt::AlignRight);
            if (shown)
                cell->setToolTip(tr("F1 %1, precision %2, recall %3: %4 found, %5 false, %6 "
                                    "missed")
                                     .arg(QString::number(f1Score(it->second), 'f', 3),
                                          QString::number(it->second.precision(), 'f', 3),
                                          QString::number(it->second.recall(), 'f', 3))
                                     .arg(it->second.tp)
                                     .arg(it->second.fp)
                                     .arg(it->second.fn));
            if (shown && (c == kFitTuned || c == kHeldTuned)) {
                const auto start = by_column[c - 1]->classes.find(name);
                if (start != by_column[c - 1]->classes.end())
                    mark(cell, f1Score(start->second), f1Score(it->second), 1);
            }
            m_scores->setItem(row, c, cell);
        }
    }
    if (std::any_of(by_column + 1, by_column + kColumns,
                    [](const TuneScore* s) { return s->boundary_median >= 0; })) {
        const int row = add_row(qs(boundaryKind().title));
        for (int c = kFitStart; c < kColumns; ++c) {
            const TuneScore& s = *by_column[c];
            const bool shown = s.boundary_median >= 0 && (held_scored || c <= kFitTuned);
            auto* cell = item(shown ? tr("%1 px").arg(QString::number(s.boundary_median, 'f', 1))
                                    : QStringLiteral("—"),
                              Qt::AlignRight);
            if (shown)
                cell->setToolTip(tr("Median per-frame error %1 px, mean %2 px")
                                     .arg(QString::number(s.boundary_median, 'f', 2),
                                          QString::number(s.boundary_mean, 'f', 2)));
            if (shown && (c == kFitTuned || c == kHeldTuned) &&
                by_column[c - 1]->boundary_median >= 0)
                mark(cell, by_column[c - 1]->boundary_median, s.boundary_median, -1);
            m_scores->setItem(row, c, cell);
        }
    }
    const int row = add_row(tr("Score"));
    QFont bold = m_scores->font();
    bold.setBold(true);
    m_scores->item(row, kClass)->setFont(bold);
    for (int c = kFitStart; c < kColumns; ++c) {
        const bool shown = held_scored || c <= kFitTuned;
        auto* cell =
            item(shown ? QString::number(by_column[c]->total, 'f', 3) : QStringLiteral("—"),
                 Qt::AlignRight);
        cell->setFont(bold);
        if (shown && (c == kFitTuned || c == kHeldTuned))
            mark(cell, by_column[c - 1]->total, by_column[c]->total, 1);
        m_scores->setItem(row, c, cell);
    }
    m_scores->resizeColumnsToContents();
    m_scores->horizontalHeader()->setStretchLastSection(false);
    m_scores->horizontalHeader()->setSectionResizeMode(kClass, QHeaderView::Stretch);
    m_scores->setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    int height = m_scores->horizontalHeader()->sizeHint().height() + 2 * m_scores->frameWidth();
    for (int i = 0; i < m_scores->rowCount(); ++i)
        height += m_scores->rowHeight(i);
    m_scores->setFixedHeight(height);
}

void FitResultDialog::fillChanges(const Pipeline& pipeline)
{
    const std::vector<const PerceptKind*> kinds = scoredKinds(pipeline.perceptKinds());
    m_changes->setRowCount(int(m_result.changes.size()));
    int row = 0;
    for (const TuneChange& change : m_result.changes) {
        const StageDescriptor* stage = pipeline.find(change.stage);
        const ParamInfo* info = nullptr;
        if (stage)
            for (const ParamInfo& p : stage->params)
                if (p.name == change.name)
                    info = &p;
        const QString stage_name =
            stage ? QString::fromStdString(stage->info.name) : QString::fromStdString(change.stage);
        auto* name = item(stage_name + QStringLiteral(": ") + QString::fromStdString(change.name));
        name->setToolTip(QStringLiteral("%1.%2%3").arg(
            QString::fromStdString(change.stage), QString::fromStdString(change.name),
            info ? QStringLiteral("\n") + QString::fromStdString(info->description) : QString()));
        m_changes->setItem(row, 0, name);
        const auto value = [info](double v) {
            return info ? paramValueText(*info, v) : QString::number(v);
        };
        m_changes->setItem(row, 1, item(value(change.before), Qt::AlignRight));
        m_changes->setItem(row, 2, item(value(change.after), Qt::AlignRight));
        auto* gain = item(signedScore(change.gain), Qt::AlignRight);
        mark(gain, 0, change.gain, 1);
        m_changes->setItem(row, 3, gain);
        QStringList terms;
        for (const auto& [term, g] : change.term_gain)
            if (std::abs(g) >= 0.0005)
                terms << termTitle(term, kinds) + ' ' + signedScore(g);
        // One class a line: the column stays narrow enough for a small screen.
        m_changes->setItem(row, 4,
                           item(terms.isEmpty() ? tr("no class moved alone") : terms.join('\n')));
        ++row;
    }
    m_changes->resizeColumnsToContents();
    m_changes->verticalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_changes->horizontalHeader()->setStretchLastSection(true);
}

void FitResultDialog::fitSize()
{
    // Both tables ask for the room their cells take, the dialog for the sum, within the screen
    // (a long list of changes scrolls).
    for (QTableWidget* table : {m_scores, m_changes})
        table->setSizeAdjustPolicy(QAbstractScrollArea::AdjustToContents);
    QSize size = sizeHint().expandedTo(QSize(560, 0));
    if (const QScreen* screen = QGuiApplication::primaryScreen())
        size = size.boundedTo(screen->availableSize() * 0.9);
    resize(size);
}

} // namespace fieldsight::ui
