// The tools of a window: made from the tool list, one checkable action each (buttons and menu
// items share them), the active one, and what it would change under the cursor. The frame view
// and the UV plane forward their mouse events here; the preview follows the cursor, the table,
// the frame and the shared settings.
#pragma once

#include "ui/tools/annotation_selection.h"
#include "ui/tools/lut_tool_settings.h"
#include "ui/tools/tool.h"

#include <QObject>

#include <memory>
#include <optional>
#include <vector>

class QAction;
class QActionGroup;

namespace fieldsight::ui {

struct WindowSettings;

class ToolManager : public QObject
{
    Q_OBJECT
public:
    ToolManager(EditingSession& session, const std::vector<ToolFactory>& tools,
                QObject* parent = nullptr);
    ~ToolManager() override;

    LutToolSettings& settings() { return m_settings; }
    /// The annotated object the annotation tools selected (the Object menu acts on it).
    AnnotationSelection& selection() { return m_selection; }
    const std::vector<std::unique_ptr<Tool>>& tools() const { return m_tools; }
    Tool* find(const QString& id) const;
    Tool& active() const { return *m_active; }
    /// Edit > Delete: the active tool's selection; false when there was none.
    bool deleteSelection() { return m_active && m_active->deleteSelection(); }
    /// Makes the tool `id` active (unknown ids are ignored); the first tool is active at first.
    void activate(const QString& id);
    /// Remembers the active tool, the LUT tools' settings and the selection's propagation (the
    /// window's settings keep them between sessions), and takes them back.
    void saveSettings(WindowSettings& settings) const;
    void restoreSettings(const WindowSettings& settings);
    /// One checkable action per tool, in the tool list's order, with its shortcut and its icon
    /// in the resources (:/icons/tools/<icon or id>.svg; none when there is no such file).
    QList<QAction*> actions() const;
    /// The actions of the tools of `group` (ToolInfo::group), in the same order.
    QList<QAction*> actions(const QString& group) const;

    // From the views.
    void press(const ToolEvent& event);
    void move(const ToolEvent& event);
    void release(const ToolEvent& event);
    /// The cursor is over image pixel `pixel` (none: off the image).
    void hover(std::optional<QPoint> pixel);
    /// A key pressed in the frame view; true when the active tool used it.
    bool key(int key) { return m_active && m_active->key(key); }

    /// What the active tool would change at the cursor (or has, mid-stroke).
    const ToolPreview& preview() const { return m_preview; }

signals:
    /// The active tool's outline (its shapes) changed.
    void outlineChanged();
    void activeChanged();
    void previewChanged();

private:
    void refreshPreview();

    LutToolSettings m_settings;
    AnnotationSelection m_selection;
    ToolContext m_context;
    std::vector<std::unique_ptr<Tool>> m_tools;
    Tool* m_active = nullptr;
    QActionGroup* m_actions = nullptr;
    std::optional<QPoint> m_hover;
    ToolPreview m_preview;
};

} // namespace fieldsight::ui
