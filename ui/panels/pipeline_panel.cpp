#include "ui/panels/pipeline_panel.h"

#include "ui/widgets/wheel_guard.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QScrollArea>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QToolButton>
#include <QVBoxLayout>

#include <cmath>

namespace fieldsight::ui {

namespace {

QString qs(const std::string& s)
{
    return QString::fromStdString(s);
}

int decimalsFor(double step)
{
    if (step <= 0)
        return 3;
    return std::clamp(int(std::ceil(-std::log10(step) - 1e-9)), 0, 6);
}

} // namespace

PipelinePanel::PipelinePanel(StreamDocument& document, PipelineSettings& settings, QWidget* parent)
    : QWidget(parent), m_doc(document), m_settings(settings)
{
    setObjectName(QStringLiteral("pipeline"));
    auto* outer = new QVBoxLayout(this);
    outer->setContentsMargins(0, 0, 0, 0);
    auto* top = new QHBoxLayout;
    auto* total = new QLabel(this);
    total->setObjectName(QStringLiteral("total_time"));
    top->addWidget(total, 1);
    m_total = total;
    auto* reset_all = new QPushButton(tr("Reset all"), this);
    reset_all->setToolTip(tr("Every parameter of every stage back to its default"));
    connect(reset_all, &QPushButton::clicked, this, [this] {
        if (Status s = m_settings.setParamChanges({}); !s)
            emit problem(qs(s.error().message));
    });
    top->addWidget(reset_all);
    outer->addLayout(top);
    // Lengths follow the frame's size (param.h, kParamReferenceWidth): said once, above them all.
    bool any_length = false;
    for (const StageDescriptor& stage : m_settings.pipeline().descriptors())
        for (const ParamInfo& param : stage.params)
            any_length = any_length || param.scales_with_width;
    if (any_length) {
        auto* note = new QLabel(tr("Lengths in px are for a frame %1 px wide; a wider or "
                                   "narrower frame scales them by its width / %1 (x4 at 1280).")
                                    .arg(kParamReferenceWidth),
                                this);
        note->setObjectName(QStringLiteral("length_note"));
        note->setWordWrap(true);
        outer->addWidget(note);
    }

    auto* scroll = new QScrollArea(this);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    auto* inner = new QWidget(scroll);
    auto* column = new QVBoxLayout(inner);
    column->setContentsMargins(4, 4, 4, 4);

    for (const StageDescriptor& stage : m_settings.pipeline().descriptors()) {
        const std::string id = stage.info.id;
        auto* box = new QGroupBox(qs(stage.info.name), inner);
        box->setObjectName(qs(id));
        box->setToolTip(qs(stage.info.description));
        box->setCheckable(stage.info.skippable);
        box->setChecked(m_settings.stageEnabled(id));
        connect(box, &QGroupBox::toggled, this, [this, id](bool on) {
            if (Status s = m_settings.setStageEnabled(id, on); !s)
                emit problem(qs(s.error().message));
        });
        auto* form = new QFormLayout(box);
        form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
        form->setRowWrapPolicy(QFormLayout::WrapLongRows); // long names above their editor
        auto* time = new QLabel(box);
        time->setObjectName(qs(id + ".time"));
        form->addRow(tr("Time"), time);
        m_stages[id] = {box, time};

        for (const ParamInfo& param : stage.params) {
            const QString key = qs(id + "." + param.name);
            ParamWidgets w{id, param, nullptr, {}, nullptr};
            const QString unit = param.unit.empty() ? QString() : ' ' + qs(param.unit);
            auto set = [this, id, name = param.name](double v) {
                if (Status s = m_settings.setParam(id, name, v); !s)
                    emit problem(qs(s.error().message));
            };
            // Whole numbers that fit an int get a QSpinBox; wider ones (a seed) and reals a
            // QDoubleSpinBox, with no decimals for whole numbers.
            const bool fits_int = param.kind == ParamKind::Integer && param.min >= -2147483647.0 &&
                                  param.max <= 2147483647.0;
            switch (param.kind) {
            case ParamKind::Integer:
                if (fits_int) {
                    auto* spin = new QSpinBox(box);
                    spin->setRange(int(param.min), int(param.max));
                    spin->setSingleStep(std::max(1, int(param.step)));
                    spin->setSuffix(unit);
                    spin->setKeyboardTracking(false);
                    connect(spin, &QSpinBox::valueChanged, this, [set](int v) { set(v); });
                    w.editor = spin;
                    w.show = [spin](double v) {
                        QSignalBlocker block(spin);
                        spin->setValue(int(std::lround(v)));
                    };
                    break;
                }
                [[fallthrough]];
            case ParamKind::Real: {
                auto* spin = new QDoubleSpinBox(box);
                spin->setDecimals(param.kind == ParamKind::Integer ? 0 : decimalsFor(param.step));
                spin->setRange(param.min, param.max);
                spin->setSingleStep(param.step);
                spin->setSuffix(unit);
                spin->setKeyboardTracking(false);
                connect(spin, &QDoubleSpinBox::valueChanged, this, set);
                w.editor = spin;
                w.show = [spin](double v) {
                    QSignalBlocker block(spin);
                    spin->setValue(v);
                };
                break;
            }
            case ParamKind::Boolean: {
                auto* check = new QCheckBox(box);
                connect(check, &QCheckBox::toggled, this, [set](bool on) { set(on ? 1 : 0); });
                w.editor = check;
                w.show = [check](double v) {
                    QSignalBlocker block(check);
                    check->setChecked(v != 0);
                };
                break;
            }
            case ParamKind::Choice: {
                auto* combo = new QComboBox(box);
                for (const ParamChoice& c : param.choices)
                    combo->addItem(qs(c.name), c.value);
                connect(combo, &QComboBox::activated, this,
                        [combo, set](int i) { set(combo->itemData(i).toInt()); });
                w.editor = combo;
                w.show = [combo](double v) {
                    QSignalBlocker block(combo);
                    combo->setCurrentIndex(combo->findData(int(std::lround(v))));
                };
                break;
            }
            }
            w.editor->setObjectName(key);
            // Narrow editors: a spin box asks for the width of its largest value otherwise.
            w.editor->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
            w.editor->setMinimumWidth(56);
            QString tip = qs(param.description);
            if (param.kind == ParamKind::Real || param.kind == ParamKind::Integer)
                tip += tr("\nRange %1 to %2%3, default %4%3")
                           .arg(param.min)
                           .arg(param.max)
                           .arg(unit)
                           .arg(param.default_value);
            if (param.scales_with_width)
                tip += tr("\nIn px at %1 wide: scaled by the frame's width / %1.")
                           .arg(kParamReferenceWidth);
            w.editor->setToolTip(tip);
            auto* reset = new QToolButton(box);
            reset->setText(QStringLiteral("↺"));
            reset->setToolTip(tr("Reset to the default (%1)").arg(param.default_value));
            reset->setObjectName(key + ".reset");
            connect(reset, &QToolButton::clicked, this,
                    [this, id, name = param.name] { m_settings.resetParam(id, name); });
            w.reset = reset;
            auto* row = new QHBoxLayout;
            row->addWidget(w.editor, 1);
            row->addWidget(reset);
            auto* label = new QLabel(qs(param.name), box);
            label->setToolTip(tip);
            form->addRow(label, row);
            m_params[key] = std::move(w);
        }
        column->addWidget(box);
    }
    column->addStretch(1);
    scroll->setWidget(inner);
    outer->addWidget(scroll, 1);
    guardWheel(inner);

    connect(&m_settings, &PipelineSettings::changed, this, &PipelinePanel::refreshValues);
    connect(&m_doc, &StreamDocument::frameReady, this, &PipelinePanel::refreshTimes);
    connect(&m_doc, &StreamDocument::streamChanged, this, &PipelinePanel::refreshTimes);
    connect(&m_doc, &StreamDocument::meansReset, this, &PipelinePanel::refreshTimes);
    refreshValues();
    refreshTimes();
}

QWidget* PipelinePanel::editor(const QString& param) const
{
    const auto it = m_params.find(param);
    return it == m_params.end() ? nullptr : it->second.editor;
}

QGroupBox* PipelinePanel::stageBox(const QString& stage_id) const
{
    const auto it = m_stages.find(stage_id.toStdString());
    return it == m_stages.end() ? nullptr : it->second.box;
}

void PipelinePanel::refreshValues()
{
    for (auto& [key, w] : m_params) {
        const double v = m_settings.paramValue(w.stage, w.info.name);
        w.show(v);
        const bool changed = m_settings.paramChanged(w.stage, w.info.name);
        w.reset->setEnabled(changed);
        QFont f = w.editor->font();
        f.setBold(changed); // a changed value stands out
        w.editor->setFont(f);
    }
    for (auto& [id, s] : m_stages) {
        QSignalBlocker block(s.box);
        s.box->setChecked(m_settings.stageEnabled(id));
    }
}

void PipelinePanel::refreshTimes()
{
    const auto& out = m_doc.current();
    const bool ran = out && out->error.isEmpty();
    auto text = [](double now, const StreamDocument::StageMean& mean) {
        const QString m = mean.frames ? QString::number(mean.mean(), 'f', 3) : QStringLiteral("–");
        return now < 0 ? tr("skipped (mean %1 ms)").arg(m)
                       : tr("%1 ms (mean %2 ms)").arg(QString::number(now, 'f', 3), m);
    };
    const auto& means = m_doc.stageMeans();
    for (auto& [id, s] : m_stages) {
        double now = -1;
        if (ran)
            for (const StageTiming& t : out->result.report.stages)
                if (t.stage == id && t.ran)
                    now = t.ms;
        const auto mean = means.find(id);
        s.time->setText(
            text(now, mean == means.end() ? StreamDocument::StageMean{} : mean->second));
    }
    m_total->setText(
        tr("All stages: ") +
        (ran ? text(out->result.report.total_ms, m_doc.totalMean()) : QStringLiteral("–")));
}

} // namespace fieldsight::ui
