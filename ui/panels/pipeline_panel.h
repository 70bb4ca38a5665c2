// The pipeline panel, made from the stage registry: per stage a switch (the paper's controller
// switches), its parameters with their units, ranges and a reset to default, and its time on this
// frame and the mean over the frames run.
#pragma once

#include "ui/document/pipeline_settings.h"
#include "ui/document/stream_document.h"

#include <QWidget>

#include <functional>
#include <map>

class QGroupBox;
class QLabel;

namespace fieldsight::ui {

class PipelinePanel : public QWidget
{
    Q_OBJECT
public:
    PipelinePanel(StreamDocument& document, PipelineSettings& settings, QWidget* parent = nullptr);

    /// The editor of a parameter ("<stage id>.<name>"), for tests.
    QWidget* editor(const QString& param) const;
    QGroupBox* stageBox(const QString& stage_id) const;

signals:
    /// A setting was refused (the document keeps the old value); the window shows `message`.
    void problem(const QString& message);

private:
    void refreshValues();
    void refreshTimes();

    StreamDocument& m_doc;
    PipelineSettings& m_settings;
    struct StageWidgets
    {
        QGroupBox* box = nullptr;
        QLabel* time = nullptr;
    };
    std::map<std::string, StageWidgets, std::less<>> m_stages;
    struct ParamWidgets
    {
        std::string stage;
        ParamInfo info;
        QWidget* editor = nullptr;
        std::function<void(double)> show; ///< puts a value in the editor without signalling
        QWidget* reset = nullptr;
    };
    std::map<QString, ParamWidgets> m_params;
    QLabel* m_total = nullptr;
};

} // namespace fieldsight::ui
