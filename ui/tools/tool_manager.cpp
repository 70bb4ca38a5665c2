#include "ui/tools/tool_manager.h"

#include "ui/document/editing_session.h"
#include "ui/settings/window_settings.h"

#include <QAction>
#include <QActionGroup>
#include <QFile>

namespace fieldsight::ui {

namespace {

/// The icon compiled in for a tool (resources/icons/tools/<icon or id>.svg), or none.
QIcon toolIcon(const ToolInfo& info)
{
    const QString path =
        QStringLiteral(":/icons/tools/%1.svg").arg(info.icon.isEmpty() ? info.id : info.icon);
    return QFile::exists(path) ? QIcon(path) : QIcon();
}

} // namespace

ToolManager::ToolManager(EditingSession& session, const std::vector<ToolFactory>& tools,
                         QObject* parent)
    : QObject(parent), m_context{session, m_settings, m_selection}
{
    m_actions = new QActionGroup(this);
    m_actions->setExclusive(true);
    std::vector<std::unique_ptr<Tool>> made;
    for (const ToolFactory& make : tools)
        for (std::unique_ptr<Tool>& tool : make(m_context))
            made.push_back(std::move(tool));
    for (std::unique_ptr<Tool>& tool : made) {
        const ToolInfo info = tool->info();
        auto* action = new QAction(toolIcon(info), info.name, this);
        action->setObjectName(QStringLiteral("tool.%1").arg(info.id));
        action->setCheckable(true);
        action->setShortcut(info.shortcut);
        action->setToolTip(
            info.shortcut.isEmpty()
                ? info.tooltip
                : QStringLiteral("%1 (%2)").arg(info.tooltip,
                                                info.shortcut.toString(QKeySequence::NativeText)));
        action->setData(info.id);
        action->setProperty("group", info.group);
        m_actions->addAction(action);
        connect(action, &QAction::triggered, this, [this, id = info.id] { activate(id); });
        connect(tool.get(), &Tool::previewChanged, this, [this, t = tool.get()] {
            if (t != m_active)
                return;
            refreshPreview();
            emit outlineChanged();
        });
        m_tools.push_back(std::move(tool));
    }
    if (!m_tools.empty()) {
        m_active = m_tools.front().get();
        m_actions->actions().front()->setChecked(true);
    }
    // What a tool would change depends on the table, the frame and the shared settings.
    connect(&session.lut(), &LutDocument::changed, this, &ToolManager::refreshPreview);
    connect(&session.stream(), &StreamDocument::frameReady, this, &ToolManager::refreshPreview);
    connect(&m_settings, &LutToolSettings::changed, this, &ToolManager::refreshPreview);
}

ToolManager::~ToolManager()
{
    blockSignals(true);
    m_tools.clear();
}

Tool* ToolManager::find(const QString& id) const
{
    for (const auto& tool : m_tools)
        if (tool->info().id == id)
            return tool.get();
    return nullptr;
}

void ToolManager::saveSettings(WindowSettings& w) const
{
    w.tool = m_active ? m_active->info().id : QString();
    w.tolerance = m_settings.tolerance();
    w.brush_radius = m_settings.brushRadius();
    w.keep_others = m_settings.keepOthers();
    w.soft_classes = m_settings.softClasses();
    w.preview = m_settings.previewOn();
    w.propagate_frames = m_selection.propagateFrames();
}

void ToolManager::restoreSettings(const WindowSettings& w)
{
    m_settings.setTolerance(w.tolerance);
    m_settings.setBrushRadius(w.brush_radius);
    m_settings.setKeepOthers(w.keep_others);
    m_settings.setSoftClasses(w.soft_classes);
    m_settings.setPreviewOn(w.preview);
    m_selection.setPropagateFrames(w.propagate_frames);
    activate(w.tool);
}

void ToolManager::activate(const QString& id)
{
    Tool* tool = find(id);
    if (!tool || tool == m_active) {
        if (tool) // an action unchecked by a click on itself
            for (QAction* a : m_actions->actions())
                a->setChecked(a->data().toString() == id);
        return;
    }
    m_active->deactivate();
    m_active = tool;
    for (QAction* a : m_actions->actions())
        a->setChecked(a->data().toString() == id);
    emit activeChanged();
    emit outlineChanged();
    refreshPreview();
}

QList<QAction*> ToolManager::actions() const
{
    return m_actions->actions();
}

QList<QAction*> ToolManager::actions(const QString& group) const
{
    QList<QAction*> out;
    for (QAction* a : m_actions->actions())
        if (a->property("group").toString() == group)
            out << a;
    return out;
}

void ToolManager::press(const ToolEvent& event)
{
    if (m_active && m_active->accepts(event.surface))
        m_active->press(event);
}

void ToolManager::move(const ToolEvent& event)
{
    if (m_active && m_active->accepts(event.surface))
        m_active->move(event);
}

void ToolManager::release(const ToolEvent& event)
{
    if (m_active && m_active->accepts(event.surface))
        m_active->release(event);
    // The edit is made: what it would change is no longer news until the pointer moves again.
    m_hover.reset();
    refreshPreview();
}

void ToolManager::hover(std::optional<QPoint> pixel)
{
    m_hover = pixel;
    if (m_active)
        m_active->hover(pixel);
    refreshPreview();
}

void ToolManager::refreshPreview()
{
    ToolPreview next = m_active ? m_active->preview(m_hover) : ToolPreview{};
    if (next.text.isEmpty() && m_preview.text.isEmpty() && next.cells.empty() &&
        m_preview.cells.empty() && next.pixels.empty() && m_preview.pixels.empty())
        return; // nothing shown before or now
    m_preview = std::move(next);
    emit previewChanged();
}

} // namespace fieldsight::ui
