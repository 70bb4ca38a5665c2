#include "ui/panels/lut_panel.h"

#include "ui/adapters/local_path.h"

#include "ui/adapters/image_adapter.h"
#include "visioncore/services/lut_compare.h"

#include <QAction>
#include <QActionGroup>
#include <QButtonGroup>
#include <QCheckBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QLabel>
#include <QMessageBox>
#include <QProgressDialog>
#include <QPushButton>
#include <QTimer>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QSignalBlocker>
#include <QSlider>
#include <QSpinBox>
#include <QToolButton>
#include <QUndoView>
#include <QVBoxLayout>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <set>

#include <array>
#include <cmath>

namespace fieldsight::ui {

namespace {

} // namespace

LutPanel::LutPanel(LutDocument& lut, StreamDocument& stream, QWidget* parent)
    : QWidget(parent), m_lut(lut), m_stream(stream)
{
    setObjectName(QStringLiteral("lut_panel"));
    auto* column = new QVBoxLayout(this);

    // The palette: a button per class; keys 0-9 choose the first ten.
    auto* palette = new QGridLayout;
    m_colours = new QActionGroup(this);
    m_colours->setExclusive(true);
    for (int c = 0; c < kColourCount; ++c) {
        auto* action = new QAction(colourSwatch(Colour(c)), colourLabel(Colour(c)), this);
        action->setObjectName(QStringLiteral("colour.%1").arg(colourLabel(Colour(c))));
        action->setCheckable(true);
        action->setData(c);
        if (c <= 9) {
            action->setShortcut(QKeySequence(Qt::Key_0 + c));
            action->setToolTip(QStringLiteral("%1 (%2)").arg(colourLabel(Colour(c))).arg(c));
        }
        m_colours->addAction(action);
        auto* button = new QToolButton(this);
        button->setDefaultAction(action);
        button->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
        button->setAutoRaise(true);
        button->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
        palette->addWidget(button, c / 2, c % 2);
    }
    connect(m_colours, &QActionGroup::triggered, this,
            [this](QAction* a) { m_colour = Colour(a->data().toInt()); });
    column->addLayout(palette);

    // The tools.
    auto* tools = new QGridLayout;
    m_tools = new QButtonGroup(this);
    const std::pair<LutTool, QString> kinds[] = {
        {LutTool::Navigate, tr("Pan")}, {LutTool::Click, tr("Click")},
        {LutTool::Brush, tr("Brush")},  {LutTool::Erase, tr("Erase")},
        {LutTool::Wand, tr("Wand")},    {LutTool::Sample, tr("Sample")}};
    int at = 0;
    for (const auto& [kind, name] : kinds) {
        auto* button = new QPushButton(name, this);
        button->setObjectName(QStringLiteral("tool.%1").arg(name.toLower()));
        button->setCheckable(true);
        m_tools->addButton(button, int(kind));
        tools->addWidget(button, 0, at++);
    }
    m_tools->button(int(LutTool::Navigate))->setChecked(true);
    m_tools->button(int(LutTool::Click))
        ->setToolTip(
            tr("Click a pixel: its colour, grown by the tolerance box, becomes the class"));
    m_tools->button(int(LutTool::Brush))
        ->setToolTip(tr("Paint over the image: every colour under the brush becomes the class"));
    m_tools->button(int(LutTool::Erase))
        ->setToolTip(tr("Paint over the image: every colour under the brush becomes unclassified"));
    m_tools->button(int(LutTool::Wand))
        ->setToolTip(tr("Click a pixel: the connected pixels of similar colour become the class"));
    m_tools->button(int(LutTool::Sample))
        ->setToolTip(tr("Drag a rectangle: a sample region of the class, kept beside the stream "
                        "to build the LUT from (and again after the light changes)"));
    connect(m_tools, &QButtonGroup::idClicked, this, [this](int id) { setTool(LutTool(id)); });
    column->addLayout(tools);

    auto* form = new QFormLayout;
    auto spin = [this](const QString& name, int max, int value) {
        auto* box = new QSpinBox(this);
        box->setObjectName(name);
        box->setRange(0, max);
        box->setValue(value);
        return box;
    };
    m_tol_y = spin(QStringLiteral("tolerance.y"), 128, 8);
    m_tol_cb = spin(QStringLiteral("tolerance.cb"), 128, 4);
    m_tol_cr = spin(QStringLiteral("tolerance.cr"), 128, 4);
    m_tol_all = new QSlider(Qt::Horizontal, this);
    m_tol_all->setObjectName(QStringLiteral("tolerance.all"));
    m_tol_all->setRange(0, 64);
    m_tol_all->setToolTip(tr("All three channels at once"));
    connect(m_tol_all, &QSlider::valueChanged, this, [this](int v) { setTolerance({v, v, v}); });
    m_radius = spin(QStringLiteral("brush.radius"), 50, 2);
    connect(m_radius, &QSpinBox::valueChanged, this, &LutPanel::announceTool);
    form->addRow(tr("Tolerance Y"), m_tol_y);
    form->addRow(tr("Tolerance Cb"), m_tol_cb);
    form->addRow(tr("Tolerance Cr"), m_tol_cr);
    form->addRow(tr("All channels"), m_tol_all);
    form->addRow(tr("Brush radius (px)"), m_radius);
    m_keep_others = new QCheckBox(tr("Only unclassified cells"), this);
    m_keep_others->setObjectName(QStringLiteral("keep_others"));
    m_keep_others->setToolTip(tr("Leave cells that already belong to another class as they are"));
    form->addRow(m_keep_others);
    m_soft = new QCheckBox(tr("Soft classes where two meet"), this);
    m_soft->setObjectName(QStringLiteral("soft_classes"));
    m_soft->setToolTip(tr("Cells where pink or yellow meets orange become pink_orange or "
                          "yellow_orange instead of changing sides"));
    form->addRow(m_soft);
    m_preview_on = new QCheckBox(tr("Preview under the cursor"), this);
    m_preview_on->setObjectName(QStringLiteral("preview_on"));
    m_preview_on->setChecked(true);
    m_preview_on->setToolTip(tr("Before you click: the pixels whose class would change are "
                                "highlighted, and the cells taken from another class counted"));
    connect(m_preview_on, &QCheckBox::toggled, this, [this](bool on) {
        if (!on)
            preview(std::nullopt);
    });
    form->addRow(m_preview_on);
    column->addLayout(form);

    // Samples: regions to build the table from, kept beside the stream.
    m_sampler = new LutSampler(m_lut, this);
    connect(m_sampler, &LutSampler::problem, this, &LutPanel::problem);
    // A samples file that cannot be read is among the warnings of opening (loadProblem).
    connect(&m_stream, &StreamDocument::streamChanged, this,
            [this] { (void)m_sampler->setStream(m_stream.streamSpec()); });
    m_samples_info = new QLabel(this);
    m_samples_info->setObjectName(QStringLiteral("samples_info"));
    m_samples_info->setWordWrap(true);
    column->addWidget(m_samples_info);
    auto* samples_row = new QHBoxLayout;
    auto* build = new QPushButton(tr("Build from samples"), this);
    build->setObjectName(QStringLiteral("samples.build"));
    connect(build, &QPushButton::clicked, this, &LutPanel::buildFromSamples);
    samples_row->addWidget(build);
    auto* undo_sample = new QPushButton(tr("Undo sample"), this);
    undo_sample->setObjectName(QStringLiteral("samples.undo"));
    connect(undo_sample, &QPushButton::clicked, &m_sampler->undoStack(), &QUndoStack::undo);
    connect(&m_sampler->undoStack(), &QUndoStack::canUndoChanged, undo_sample,
            &QWidget::setEnabled);
    undo_sample->setEnabled(false);
    samples_row->addWidget(undo_sample);
    auto* ambiguous = new QPushButton(tr("Ambiguous cells"), this);
    ambiguous->setObjectName(QStringLiteral("samples.ambiguous"));
    ambiguous->setToolTip(tr("Outline in the UV plane the cells the last build found claimed by "
                             "two classes' samples"));
    connect(ambiguous, &QPushButton::clicked, this, [this] {
        std::vector<std::uint32_t> cells;
        for (const AmbiguousCell& c : m_sampler->ambiguous())
            cells.push_back(c.cell);
        emit cellsToOutline(cells);
    });
    samples_row->addWidget(ambiguous);
    column->addLayout(samples_row);
    m_samples_annotations = new QCheckBox(tr("and the stream's annotations"), this);
    m_samples_annotations->setObjectName(QStringLiteral("samples.annotations"));
    m_samples_annotations->setToolTip(tr("Balls orange, posts the goal colour, the field green, "
                                         "lines white, above the field and robots unclassified"));
    column->addWidget(m_samples_annotations);
    const auto describe = [this] {
        std::set<std::string> frames;
        for (const LutSample& s : m_sampler->samples().samples)
            frames.insert(s.frame);
        m_samples_info->setText(
            tr("Samples: %1 on %2 frames%3")
                .arg(qulonglong(m_sampler->samples().samples.size()))
                .arg(qulonglong(frames.size()))
                .arg(m_sampler->path().isEmpty()
                         ? QString()
                         : tr(" (%1)").arg(QFileInfo(m_sampler->path()).fileName())));
    };
    connect(m_sampler, &LutSampler::samplesChanged, this, describe);
    describe();
    connect(m_sampler, &LutSampler::built, this, [this](bool ok, const QString& summary) {
        m_samples_info->setText(summary);
        if (!ok)
            emit problem(summary);
    });

    auto* retarget_button = new QPushButton(tr("Retarget to this frame's field…"), this);
    retarget_button->setObjectName(QStringLiteral("retarget"));
    retarget_button->setToolTip(tr("At a new venue: move the whole table by the shift between "
                                   "its green and the field at the bottom of this frame"));
    connect(retarget_button, &QPushButton::clicked, this, &LutPanel::askRetarget);
    column->addWidget(retarget_button);

    m_preview_label = new QLabel(this);
    m_preview_label->setObjectName(QStringLiteral("lut_preview"));
    m_preview_label->setWordWrap(true);
    column->addWidget(m_preview_label);

    m_stats = new QLabel(this);
    m_stats->setObjectName(QStringLiteral("lut_stats"));
    m_stats->setWordWrap(true);
    column->addWidget(m_stats);

    auto* history = new QUndoView(&m_lut.undoStack(), this);
    history->setObjectName(QStringLiteral("lut_history"));
    history->setEmptyLabel(tr("<loaded table>"));
    column->addWidget(history, 1);

    setColour(Colour::Orange);
    connect(&m_lut, &LutDocument::changed, this, &LutPanel::refreshStats);
    refreshStats();
}

void LutPanel::setTool(LutTool tool)
{
    m_tool = tool;
    if (QAbstractButton* b = m_tools->button(int(tool)))
        b->setChecked(true);
    announceTool();
}

void LutPanel::announceTool()
{
    const bool brush = m_tool == LutTool::Brush || m_tool == LutTool::Erase;
    emit toolChanged(m_tool != LutTool::Navigate, brush ? brushRadius() : -1);
}

void LutPanel::setColour(Colour colour)
{
    m_colour = colour;
    for (QAction* a : m_colours->actions())
        if (a->data().toInt() == int(colour))
            a->setChecked(true);
}

Tolerance LutPanel::tolerance() const
{
    return {m_tol_y->value(), m_tol_cb->value(), m_tol_cr->value()};
}

void LutPanel::setTolerance(const Tolerance& t)
{
    m_tol_y->setValue(t.y);
    m_tol_cb->setValue(t.cb);
    m_tol_cr->setValue(t.cr);
}

int LutPanel::brushRadius() const
{
    return m_radius->value();
}

void LutPanel::setBrushRadius(int radius)
{
    m_radius->setValue(radius);
}

bool LutPanel::keepOthers() const
{
    return m_keep_others->isChecked();
}

bool LutPanel::softClasses() const
{
    return m_soft->isChecked();
}

void LutPanel::setSoftClasses(bool on)
{
    m_soft->setChecked(on);
}

QList<QAction*> LutPanel::colourActions() const
{
    return m_colours->actions();
}

const cv::Mat* LutPanel::frame() const
{
    const auto& out = m_stream.current();
    if (!out || out->frame.ycbcr.empty())
        return nullptr;
    return &out->frame.ycbcr;
}

std::optional<PlannedEdit> LutPanel::planAt(QPoint pixel) const
{
    const cv::Mat* image = frame();
    if (!image || pixel.x() < 0 || pixel.y() < 0 || pixel.x() >= image->cols ||
        pixel.y() >= image->rows)
        return std::nullopt;
    const cv::Point at(pixel.x(), pixel.y());
    const Tolerance t = tolerance();
    const bool keep = m_keep_others->isChecked();
    switch (m_tool) {
    case LutTool::Navigate:
    case LutTool::Sample:
        return std::nullopt;
    case LutTool::Click: {
        const cv::Vec3b c = image->at<cv::Vec3b>(at);
        return PlannedEdit{tr("Click (%1, %2, %3) ± (%4, %5, %6) → %7")
                               .arg(c[0])
                               .arg(c[1])
                               .arg(c[2])
                               .arg(t.y)
                               .arg(t.cb)
                               .arg(t.cr)
                               .arg(colourLabel(m_colour)),
                           changesTo(m_lut.table(), cellsInBox(c[0], c[1], c[2], t), m_colour, keep,
                                     softClasses())};
    }
    case LutTool::Wand: {
        const std::vector<cv::Point> pixels = wandPixels(*image, at, t);
        return PlannedEdit{
            tr("Wand at (%1, %2): %3 px → %4")
                .arg(pixel.x())
                .arg(pixel.y())
                .arg(qsizetype(pixels.size()))
                .arg(colourLabel(m_colour)),
            changesTo(m_lut.table(), cellsOfPixels(*image, pixels), m_colour, keep, softClasses())};
    }
    case LutTool::Brush:
    case LutTool::Erase:
        return brushEdit(brushPixels(at, brushRadius(), image->size()));
    }
    return std::nullopt;
}

PlannedEdit LutPanel::brushEdit(const std::vector<cv::Point>& pixels) const
{
    const bool erase = m_tool == LutTool::Erase;
    const Colour target = erase ? Colour::Unclassified : m_colour;
    const Tolerance t = erase ? Tolerance{} : tolerance();
    const bool keep = !erase && m_keep_others->isChecked();
    return PlannedEdit{erase ? tr("Erase stroke")
                             : tr("Brush stroke → %1").arg(colourLabel(m_colour)),
                       changesTo(m_lut.table(), cellsOfPixels(*frame(), pixels, t), target, keep,
                                 !erase && softClasses())};
}

void LutPanel::buildFromSamples()
{
    if (m_sampler->building())
        return;
    m_sampler->build(m_samples_annotations->isChecked());
    auto* progress =
        new QProgressDialog(tr("Building the LUT from samples…"), tr("Cancel"), 0, 0, this);
    progress->setObjectName(QStringLiteral("samples.progress"));
    progress->setAttribute(Qt::WA_DeleteOnClose);
    progress->setMinimumDuration(300);
    connect(progress, &QProgressDialog::canceled, m_sampler, &LutSampler::cancel);
    auto* poll = new QTimer(progress);
    connect(poll, &QTimer::timeout, progress, [this, progress] {
        const auto [done, total] = m_sampler->progress();
        progress->setMaximum(int(total));
        progress->setValue(int(done));
        if (!m_sampler->building())
            progress->close();
    });
    poll->start(100);
}

void LutPanel::press(QPoint pixel)
{
    if (m_tool == LutTool::Sample) {
        m_sample_from = m_sample_to = pixel;
        return;
    }
    if (m_tool == LutTool::Brush || m_tool == LutTool::Erase) {
        m_stroke = m_lut.newStroke();
        m_last.reset();
        m_last_edit_cells.clear();
        paintAt(pixel);
        return;
    }
    if (auto plan = planAt(pixel)) {
        m_last_edit_cells.clear();
        for (const CellChange& c : plan->changes)
            m_last_edit_cells.push_back(c.cell);
        m_lut.edit(plan->text, std::move(plan->changes));
        preview(pixel); // what another click here would do now
    }
}

void LutPanel::drag(QPoint pixel)
{
    if (m_tool == LutTool::Sample && m_sample_from) {
        m_sample_to = pixel;
        if (const cv::Mat* image = frame()) { // the rectangle so far, in the image
            cv::Mat mask(image->rows, image->cols, CV_8U, cv::Scalar(0));
            const QRect r = QRect(*m_sample_from, *m_sample_to).normalized();
            cv::rectangle(mask, cv::Rect(r.left(), r.top(), r.width(), r.height()), cv::Scalar(255),
                          cv::FILLED);
            emit previewChanged(mask, {});
        }
        return;
    }
    if (m_stroke && (m_tool == LutTool::Brush || m_tool == LutTool::Erase))
        paintAt(pixel);
}

void LutPanel::release()
{
    if (m_tool == LutTool::Sample && m_sample_from && m_sample_to) {
        const QRect r = QRect(*m_sample_from, *m_sample_to).normalized();
        const auto& out = m_stream.current();
        if (out && r.width() >= 2 && r.height() >= 2)
            m_sampler->addRect(fromLocalPath(out->frame.name), m_colour, r);
        m_sample_from.reset();
        m_sample_to.reset();
        emit previewChanged({}, {});
        return;
    }
    m_stroke = 0;
    m_last.reset();
}

void LutPanel::paintAt(QPoint pixel)
{
    const cv::Mat* image = frame();
    if (!image)
        return;
    // Every pixel the brush passed over since the last event (a fast drag skips pixels).
    const QPoint from = m_last.value_or(pixel);
    const int steps = std::max({1, std::abs(pixel.x() - from.x()), std::abs(pixel.y() - from.y())});
    std::vector<cv::Point> pixels;
    for (int i = m_last ? 1 : 0; i <= steps; ++i) {
        const cv::Point centre(
            int(std::lround(from.x() + (pixel.x() - from.x()) * i / double(steps))),
            int(std::lround(from.y() + (pixel.y() - from.y()) * i / double(steps))));
        const auto disc = brushPixels(centre, brushRadius(), image->size());
        pixels.insert(pixels.end(), disc.begin(), disc.end());
    }
    m_last = pixel;
    PlannedEdit plan = brushEdit(pixels);
    for (const CellChange& c : plan.changes)
        m_last_edit_cells.push_back(c.cell);
    m_lut.edit(plan.text, std::move(plan.changes), m_stroke);
}

void LutPanel::preview(std::optional<QPoint> pixel)
{
    if (m_stroke) { // mid-stroke: what the stroke has changed so far
        m_preview.clear();
        cv::Mat pixels;
        if (const cv::Mat* image = frame(); image && !m_last_edit_cells.empty())
            pixels = pixelsIn(*image, CellMask::of(m_last_edit_cells));
        m_preview_label->setText(
            tr("Stroke: %1 cells changed").arg(qsizetype(m_last_edit_cells.size())));
        emit previewChanged(pixels, m_last_edit_cells);
        return;
    }
    std::optional<PlannedEdit> plan;
    if (pixel && m_preview_on->isChecked())
        plan = planAt(*pixel);
    m_preview = plan ? std::move(plan->changes) : std::vector<CellChange>{};
    cv::Mat pixels;
    std::vector<std::uint32_t> cells;
    if (!m_preview.empty()) {
        pixels = pixelsIn(*frame(), CellMask::of(m_preview));
        cells.reserve(m_preview.size());
        for (const CellChange& c : m_preview)
            cells.push_back(c.cell);
    }
    // Overlap: cells the edit would take from another class, by class.
    std::array<std::size_t, kColourCount> taken{};
    for (const CellChange& c : m_preview)
        if (c.before != Colour::Unclassified)
            ++taken[std::size_t(c.before)];
    QString text;
    if (!m_preview.empty()) {
        QStringList overlap;
        for (int c = 1; c < kColourCount; ++c)
            if (taken[std::size_t(c)] > 0)
                overlap << QStringLiteral("%1 %2")
                               .arg(taken[std::size_t(c)])
                               .arg(colourLabel(Colour(c)));
        text = tr("Here: %1 cells would change, %2 px of this frame")
                   .arg(qsizetype(m_preview.size()))
                   .arg(cv::countNonZero(pixels));
        text += overlap.isEmpty()
                    ? tr("; none taken from another class")
                    : tr("; taken from another class: %1").arg(overlap.join(QStringLiteral(", ")));
    }
    m_preview_label->setText(text);
    emit previewChanged(pixels, cells);
}

ColourShift LutPanel::estimateRetarget(std::size_t* samples) const
{
    std::vector<cv::Vec3b> field;
    if (const cv::Mat* image = frame())
        for (int y = image->rows * 2 / 3; y < image->rows; ++y)
            for (int x = 0; x < image->cols; ++x)
                field.push_back(image->at<cv::Vec3b>(y, x));
    if (samples)
        *samples = field.size();
    return estimateShift(m_lut.table(), Colour::Green, field);
}

bool LutPanel::retarget(const ColourShift& shift)
{
    return m_lut.edit(tr("Retarget by Y %1, Cb %2, Cr %3").arg(shift.y).arg(shift.cb).arg(shift.cr),
                      shiftChanges(m_lut.table(), shift));
}

void LutPanel::askRetarget()
{
    std::size_t samples = 0;
    const ColourShift shift = estimateRetarget(&samples);
    const std::size_t cells = shiftChanges(m_lut.table(), shift).size();
    if (cells == 0) {
        QMessageBox::information(this, tr("Retarget LUT"),
                                 tr("The table's green already matches this frame's field (or "
                                    "the table has no green): nothing to move."));
        return;
    }
    const auto answer = QMessageBox::question(
        this, tr("Retarget LUT"),
        tr("This frame's field (its bottom third, %1 pixels) against the table's green says the "
           "light moved by Y %2, Cb %3, Cr %4 levels.\n\nMoving the whole table by that "
           "changes %5 cells (one undo step). Apply?")
            .arg(qulonglong(samples))
            .arg(shift.y)
            .arg(shift.cb)
            .arg(shift.cr)
            .arg(qulonglong(cells)));
    if (answer == QMessageBox::Yes)
        retarget(shift);
}

QString LutPanel::previewText() const
{
    return m_preview_label->text();
}

void LutPanel::pick(QPoint pixel)
{
    const auto& out = m_stream.current();
    if (!out || out->classes.empty() || pixel.x() < 0 || pixel.y() < 0 ||
        pixel.x() >= out->classes.cols || pixel.y() >= out->classes.rows)
        return;
    setColour(Colour(out->classes.at<std::uint8_t>(pixel.y(), pixel.x())));
}

void LutPanel::refreshStats()
{
    const std::vector<std::size_t> counts = cellsPerClass(m_lut.table());
    QStringList lines;
    for (int c = 1; c < kColourCount; ++c)
        if (counts[std::size_t(c)] > 0)
            lines
                << QStringLiteral("%1 %2").arg(colourLabel(Colour(c))).arg(counts[std::size_t(c)]);
    m_stats->setText(
        tr("Cells per class: %1")
            .arg(lines.isEmpty() ? tr("none classified") : lines.join(QStringLiteral(", "))));
}

} // namespace fieldsight::ui
