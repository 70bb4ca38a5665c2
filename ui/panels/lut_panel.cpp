#include "ui/panels/lut_panel.h"

#include "ui/adapters/image_adapter.h"
#include "ui/dialogs/dialogs.h"

#include <QAction>
#include <QActionGroup>
#include <QCheckBox>
#include <QFileInfo>
#include <QFormLayout>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QProgressDialog>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSlider>
#include <QSpinBox>
#include <QTimer>
#include <QToolButton>
#include <QVBoxLayout>

#include <set>

namespace fieldsight::ui {

namespace {

const cv::Mat* currentFrame(const StreamDocument& stream)
{
    const auto& out = stream.current();
    return out && !out->frame.ycbcr.empty() ? &out->frame.ycbcr : nullptr;
}

QSpinBox* spinBox(QWidget* parent, const QString& name, int max)
{
    auto* box = new QSpinBox(parent);
    box->setObjectName(name);
    box->setRange(0, max);
    return box;
}

} // namespace

LutPanel::LutPanel(LutDocument& lut, StreamDocument& stream, SamplesDocument& samples,
                   ToolManager& tools, QWidget* parent)
    : QWidget(parent), m_lut(lut), m_stream(stream), m_samples(samples), m_tools(tools)
{
    setObjectName(QStringLiteral("lut_panel"));
    LutToolSettings& settings = m_tools.settings();
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
            [&settings](QAction* a) { settings.setColour(Colour(a->data().toInt())); });
    column->addLayout(palette);

    // A button per tool, from the tool list (they share the window's actions and shortcuts).
    auto* tool_row = new QGridLayout;
    int at = 0;
    for (QAction* action : m_tools.actions()) {
        auto* button = new QToolButton(this);
        button->setObjectName(action->objectName());
        button->setDefaultAction(action);
        button->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
        button->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
        tool_row->addWidget(button, at / 3, at % 3);
        ++at;
    }
    column->addLayout(tool_row);

    auto* form = new QFormLayout;
    m_tol_y = spinBox(this, QStringLiteral("tolerance.y"), 128);
    m_tol_cb = spinBox(this, QStringLiteral("tolerance.cb"), 128);
    m_tol_cr = spinBox(this, QStringLiteral("tolerance.cr"), 128);
    m_tol_all = new QSlider(Qt::Horizontal, this);
    m_tol_all->setObjectName(QStringLiteral("tolerance.all"));
    m_tol_all->setRange(0, 64);
    m_tol_all->setToolTip(tr("All three channels at once"));
    m_radius = spinBox(this, QStringLiteral("brush.radius"), 50);
    const auto tolerance = [this, &settings] {
        settings.setTolerance({m_tol_y->value(), m_tol_cb->value(), m_tol_cr->value()});
    };
    for (QSpinBox* box : {m_tol_y, m_tol_cb, m_tol_cr})
        connect(box, &QSpinBox::valueChanged, this, tolerance);
    connect(m_tol_all, &QSlider::valueChanged, this, [&settings](int v) {
        settings.setTolerance({v, v, v});
    });
    connect(m_radius, &QSpinBox::valueChanged, &settings, &LutToolSettings::setBrushRadius);
    form->addRow(tr("Tolerance Y"), m_tol_y);
    form->addRow(tr("Tolerance Cb"), m_tol_cb);
    form->addRow(tr("Tolerance Cr"), m_tol_cr);
    form->addRow(tr("All channels"), m_tol_all);
    form->addRow(tr("Brush radius (px)"), m_radius);
    m_keep_others = new QCheckBox(tr("Only unclassified cells"), this);
    m_keep_others->setObjectName(QStringLiteral("keep_others"));
    m_keep_others->setToolTip(tr("Leave cells that already belong to another class as they are"));
    connect(m_keep_others, &QCheckBox::toggled, &settings, &LutToolSettings::setKeepOthers);
    form->addRow(m_keep_others);
    m_soft = new QCheckBox(tr("Soft classes where two meet"), this);
    m_soft->setObjectName(QStringLiteral("soft_classes"));
    m_soft->setToolTip(tr("Cells where pink or yellow meets orange become pink_orange or "
                          "yellow_orange instead of changing sides"));
    connect(m_soft, &QCheckBox::toggled, &settings, &LutToolSettings::setSoftClasses);
    form->addRow(m_soft);
    m_preview_on = new QCheckBox(tr("Preview under the cursor"), this);
    m_preview_on->setObjectName(QStringLiteral("preview_on"));
    m_preview_on->setToolTip(tr("Before you click: the pixels whose class would change are "
                                "highlighted, and the cells taken from another class counted"));
    connect(m_preview_on, &QCheckBox::toggled, &settings, &LutToolSettings::setPreviewOn);
    form->addRow(m_preview_on);
    column->addLayout(form);

    // Samples: regions to build the table from, kept beside the stream.
    m_samples_info = new QLabel(this);
    m_samples_info->setObjectName(QStringLiteral("samples_info"));
    m_samples_info->setWordWrap(true);
    column->addWidget(m_samples_info);
    auto* samples_row = new QHBoxLayout;
    auto* build = new QPushButton(tr("Build from samples"), this);
    build->setObjectName(QStringLiteral("samples.build"));
    connect(build, &QPushButton::clicked, this, &LutPanel::buildFromSamples);
    samples_row->addWidget(build);
    auto* ambiguous = new QPushButton(tr("Ambiguous cells"), this);
    ambiguous->setObjectName(QStringLiteral("samples.ambiguous"));
    ambiguous->setToolTip(tr("Outline in the UV plane the cells the last build found claimed by "
                             "two classes' samples"));
    connect(ambiguous, &QPushButton::clicked, this, [this] {
        std::vector<std::uint32_t> cells;
        for (const AmbiguousCell& c : m_samples.ambiguous())
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
        for (const LutSample& s : m_samples.samples().samples)
            frames.insert(s.frame);
        m_samples_info->setText(
            tr("Samples: %1 on %2 frames%3")
                .arg(qulonglong(m_samples.samples().samples.size()))
                .arg(qulonglong(frames.size()))
                .arg(m_samples.path().isEmpty()
                         ? QString()
                         : tr(" (%1)").arg(QFileInfo(m_samples.path()).fileName())));
    };
    connect(&m_samples, &SamplesDocument::samplesChanged, this, describe);
    describe();
    connect(&m_samples, &SamplesDocument::built, this, [this](bool ok, const QString& summary) {
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
    connect(&m_tools, &ToolManager::previewChanged, this,
            [this] { m_preview_label->setText(m_tools.preview().text); });

    m_stats = new QLabel(this);
    m_stats->setObjectName(QStringLiteral("lut_stats"));
    m_stats->setWordWrap(true);
    column->addWidget(m_stats);
    column->addStretch(1);

    connect(&settings, &LutToolSettings::changed, this, &LutPanel::showSettings);
    showSettings();
    connect(&m_lut, &LutDocument::changed, this, &LutPanel::refreshStats);
    refreshStats();
}

void LutPanel::showSettings()
{
    const LutToolSettings& s = m_tools.settings();
    for (QAction* a : m_colours->actions())
        if (a->data().toInt() == int(s.colour()))
            a->setChecked(true);
    const std::pair<QSpinBox*, int> values[] = {{m_tol_y, s.tolerance().y},
                                                {m_tol_cb, s.tolerance().cb},
                                                {m_tol_cr, s.tolerance().cr},
                                                {m_radius, s.brushRadius()}};
    for (const auto& [box, value] : values) {
        const QSignalBlocker quiet(box);
        box->setValue(value);
    }
    const std::pair<QCheckBox*, bool> checks[] = {
        {m_keep_others, s.keepOthers()}, {m_soft, s.softClasses()}, {m_preview_on, s.previewOn()}};
    for (const auto& [box, on] : checks) {
        const QSignalBlocker quiet(box);
        box->setChecked(on);
    }
}

QList<QAction*> LutPanel::colourActions() const
{
    return m_colours->actions();
}

void LutPanel::buildFromSamples()
{
    if (m_samples.building())
        return;
    m_samples.build(m_samples_annotations->isChecked());
    auto* progress =
        new QProgressDialog(tr("Building the LUT from samples…"), tr("Cancel"), 0, 0, this);
    progress->setObjectName(QStringLiteral("samples.progress"));
    progress->setAttribute(Qt::WA_DeleteOnClose);
    progress->setMinimumDuration(300);
    connect(progress, &QProgressDialog::canceled, &m_samples, &SamplesDocument::cancel);
    auto* poll = new QTimer(progress);
    connect(poll, &QTimer::timeout, progress, [this, progress] {
        const auto [done, total] = m_samples.progress();
        progress->setMaximum(int(total));
        progress->setValue(int(done));
        if (!m_samples.building())
            progress->close();
    });
    poll->start(100);
}

ColourShift LutPanel::estimateRetarget(std::size_t* samples) const
{
    std::vector<cv::Vec3b> field;
    if (const cv::Mat* image = currentFrame(m_stream))
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
        Dialogs::current().information(
            this, tr("Retarget LUT"),
            tr("The table's green already matches this frame's field (or "
               "the table has no green): nothing to move."));
        return;
    }
    const auto answer = Dialogs::current().question(
        this, tr("Retarget LUT"),
        tr("This frame's field (its bottom third, %1 pixels) against the table's green says the "
           "light moved by Y %2, Cb %3, Cr %4 levels.\n\nMoving the whole table by that "
           "changes %5 cells (one undo step). Apply?")
            .arg(qulonglong(samples))
            .arg(shift.y)
            .arg(shift.cb)
            .arg(shift.cr)
            .arg(qulonglong(cells)),
        QMessageBox::Yes | QMessageBox::No, QMessageBox::Yes);
    if (answer == QMessageBox::Yes)
        retarget(shift);
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
