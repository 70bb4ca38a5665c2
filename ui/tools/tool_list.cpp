// THE tools, in the order of their buttons and menu items: adding a tool is its class and one
// line here.
#include "ui/tools/annotate_tool.h"
#include "ui/tools/brush_tool.h"
#include "ui/tools/click_tool.h"
#include "ui/tools/pan_tool.h"
#include "ui/tools/sample_tool.h"
#include "ui/tools/wand_tool.h"

namespace fieldsight::ui {

std::vector<ToolFactory> standardTools()
{
    return {
        toolFactory<PanTool>(),   toolFactory<ClickTool>(), toolFactory<BrushTool>(),
        toolFactory<EraseTool>(), toolFactory<WandTool>(),  toolFactory<SampleTool>(),
        annotateTools(), // one per kind the pipeline draws by hand
    };
}

} // namespace fieldsight::ui
