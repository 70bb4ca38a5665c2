#include "ui/panels/lut_panel.h"

#include "ui/adapters/image_adapter.h"
#include "ui/dialogs/dialogs.h"
#include "ui/widgets/progress_poll.h"
#include "ui/widgets/wheel_guard.h"

#include "visioncore/services/lut_compare.h"

#include <QAction>
#include <QActionGroup>
#include <QCheckBox>
#include <QFileInfo>
#include <QFormLayout>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSlider>
#include <QSpinBox>
#include <QToolButton>
#include <QVBoxLayout>

#include <array>
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

QString number(std::size_t n)
{
    return QLocale().toString(qulonglong(n));
}

/// What `changes` would do to `lut`: cells gained and lost per class, and the pixels of `frame`
/// (if any) whose class changes.
QString changeSummary(const ColourLut& lut, const std::vector<CellChange>& changes,
                      const cv::Mat* frame)
{
    std::array<std::size_t, kColourCount> gained{};
    std::array<std::size_t, kColourCount> lost{};
    for (const CellChange& c : changes) {
        ++gained[std::size_t(c.after)];
        ++lost[std::size_t(c.before)];
    }
    QStringList classes;
    for (int c = 1; c < kColourCount; ++c) {
        QStringList parts;
        if (gained[std::size_t(c)] > 0)
            parts << QStringLiteral("+") + number(gained[std::size_t(c)]);
        if (lost[std::size_t(c)] > 0)
            parts << QStringLiteral("\u2212") + number(lost[std::size_t(c)]);
        if (!parts.isEmpty())
            classes << colourLabel(Colour(c)) + QLatin1Char(' ') + parts.join(QLatin1Char(' '));
    }
    QString text = LutPanel::tr("%1 cells").arg(number(changes.size()));
    if (!classes.isEmpty())
        text += QStringLiteral(" (") + classes.join(QStringLiteral(", ")) + QLatin1Char(')');
    if (frame) {
        const PixelTally tally = PixelTallier(lut, CellMask::of(changes))(*frame);
        text += LutPanel::tr("; %1 of this frame's %2 pixels change class")
                    .arg(number(tally.in_mask), number(tally.pixels));
    }
    return text;
}

} // namespace

LutPanel::LutPanel(LutDocument& lut, StreamDocument& stream, SamplesDocument& samples,
                   ToolManager& tools, QWidget* parent)
    : QWidget(parent), m_lut(lut), m_stream(stream), m_samples(samples), m_tools(tools)
{
    setObjectName(QStringLiteral("lut_panel"));
    LutToolSettings& settings = m_tools.settings();
    auto* column = new QVBoxLayout(this);

    // The palette: a button per class in id order, each showing its key (0-9, then '-').
    auto* palette = new QGridLayout;
    m_palette = palette;
    m_colours = new QActionGroup(this);
    m_colours->setExclusive(true);
    for (int c = 0; c < kColourCount; ++c) {
        const QKeySequence key = c <= 9 ? QKeySequence(Qt::Key_0 + c) : QKeySequence(Qt::Key_Minus);
        const QString name = colourLabel(Colour(c));
        auto* action = new QAction(colourSwatch(Colour(c)), name, this);
        action->setObjectName(QStringLiteral("colour.%1").arg(name));
        action->setCheckable(true);
        action->setData(c);
        action->setShortcut(key);
        action->setIconText(
            QStringLiteral("%1  %2").arg(key.toString(QKeySequence::NativeText), name));
        action->setToolTip(QStringLiteral("%1 (%2)").arg(name, key.toString()));
        m_colours->addAction(action);
        auto* button = new QToolButton(this);
        button->setObjectName(QStringLiteral("colour_button.%1").arg(name));
        button->setDefaultAction(action);
        button->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
        button->setAutoRaise(true);
        button->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
        palette->addWidget(button, c / 2, c % 2);
    }
    connect(m_colours, &QActionGroup::triggered, this,
            [&settings](QAction* a) { settings.setColour(Colour(a->data().toInt())); });
    column->addLayout(palette);

    // A button per LUT tool, from the tool list (they share the window's actions and shortcuts;
    // the annotation tools have their own bar).
    auto* tool_row = new QGridLayout;
    int at = 0;
    for (QAction* action : m_tools.actions(QString())) {
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
    // Return in a box hands the keys back to the window, so the next 2 or W chooses a class or
    // a tool instead of typing into the box (a focus-out leaves the focus where it went).
    for (QSpinBox* box : {m_tol_y, m_tol_cb, m_tol_cr, m_radius})
        connect(box, &QSpinBox::editingFinished, this, [this, box] {
            if (box->hasFocus())
                window()->setFocus();
        });
    connect(m_tol_all, &QSlider::valueChanged, this, [&settings](int v) {
        settings.setTolerance({v, v, v});
    });
    connect(m_radius, &QSpinBox::valueChanged, &settings, &LutToolSettings::setBrushRadius);
    // Compact rows, so every control fits the dock at 1280x800 without scrolling.
    auto* tolerances = new QHBoxLayout;
    for (const auto& [label, box] : {std::pair{tr("Y"), m_tol_y}, std::pair{tr("Cb"), m_tol_cb},
                                     std::pair{tr("Cr"), m_tol_cr}}) {
        auto* name = new QLabel(label, this);
        name->setBuddy(box);
        tolerances->addWidget(name);
        tolerances->addWidget(box, 1);
    }
    form->addRow(tr("Tolerance"), tolerances);
    auto* all_row = new QHBoxLayout;
    all_row->addWidget(m_tol_all, 2);
    auto* brush_label = new QLabel(tr("Brush (px)"), this);
    brush_label->setBuddy(m_radius);
    all_row->addWidget(brush_label);
    all_row->addWidget(m_radius, 1);
    form->addRow(tr("All"), all_row);
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
    connect(&m_samples, &SamplesDocument::buildReady, this, &LutPanel::askApplyBuild);
    connect(&m_samples, &SamplesDocument::built, this, [this](bool ok, const QString& summary) {
        m_samples_info->setText(summary);
        if (!ok)
            emit problem(summary);
    });

    auto* retarget_button = new QPushButton(tr("Retarget to field…"), this);
    retarget_button->setObjectName(QStringLiteral("retarget"));
    retarget_button->setToolTip(tr("At a new venue: move the whole table by the shift between "
                                   "its green and the field at the bottom of this frame"));
    connect(retarget_button, &QPushButton::clicked, this, &LutPanel::askRetarget);

    auto* clear = new QPushButton(tr("Clear class"), this);
    clear->setObjectName(QStringLiteral("clear_class"));
    clear->setToolTip(tr("Every cell of the chosen class becomes unclassified (one undo step)"));
    connect(clear, &QPushButton::clicked, this, [this] {
        const Colour colour = m_tools.settings().colour();
        const std::size_t cells = m_lut.clearClass(colour);
        emit notice(cells == 0 ? tr("The table has no %1 cells").arg(colourLabel(colour))
                               : tr("Cleared %1 %2 cells (Ctrl+Z undoes it)")
                                     .arg(number(cells), colourLabel(colour)));
    });
    auto* table_row = new QHBoxLayout;
    table_row->addWidget(retarget_button);
    table_row->addWidget(clear);
    column->addLayout(table_row);

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
    guardWheel(this);
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

void LutPanel::addTableAction(QAction* action)
{
    // In the palette's cells after the last class: the dock has no height to spare for a row of
    // its own at 1280x800, and a table made whole belongs beside the classes it fills.
    auto* button = new QToolButton(this);
    button->setObjectName(action->objectName());
    button->setDefaultAction(action);
    button->setToolButtonStyle(Qt::ToolButtonTextOnly);
    button->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
    const int at = kColourCount + m_table_actions++;
    m_palette->addWidget(button, at / 2, at % 2);
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
    showProgress(this, tr("Building the LUT from samples…"), QStringLiteral("samples.progress"),
                 {[this] { return m_samples.progress(); }, [this] { return m_samples.building(); },
                  [this] { m_samples.cancel(); }});
}

void LutPanel::askApplyBuild()
{
    using Mode = SamplesDocument::BuildMode;
    const cv::Mat* frame = currentFrame(m_stream);
    const QString text =
        tr("The table built from the samples would change:\n\n"
           "Only unclassified cells: %1.\n\nReplace the table: %2.\n\n"
           "Either is one undo step.")
            .arg(
                changeSummary(m_lut.table(), m_samples.buildChanges(Mode::OnlyUnclassified), frame),
                changeSummary(m_lut.table(), m_samples.buildChanges(Mode::Replace), frame));
    const int answer =
        Dialogs::current().choice(this, tr("Build from samples"), text,
                                  {tr("Only unclassified cells"), tr("Replace the table")}, 0);
    if (answer < 0) {
        m_samples.dropBuild();
        m_samples_info->setText(tr("Build not applied; the LUT is unchanged"));
        return;
    }
    m_samples.applyBuild(answer == 0 ? Mode::OnlyUnclassified : Mode::Replace);
}

void LutPanel::askRetarget()
{
    std::size_t samples = 0;
    const ColourShift shift = m_lut.estimateRetarget(currentFrame(m_stream), &samples);
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
        m_lut.retarget(shift);
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
