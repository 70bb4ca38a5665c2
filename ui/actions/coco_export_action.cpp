// File > Export annotations as COCO: the annotations document's truth in COCO JSON.
#include "ui/actions/coco_export_action.h"

#include "ui/actions/menus.h"
#include "ui/adapters/local_path.h"
#include "ui/document/editing_session.h"
#include "visioncore/basics/atomic_file.h"
#include "visioncore/basics/output_guard.h"
#include "visioncore/io/coco_export.h"

namespace fieldsight::ui {

bool exportAnnotationsAsCoco(const MenuTarget& target, const QString& path)
{
    StreamDocument& stream = target.session.stream();
    const auto fail = [&target](const std::string& message) {
        target.showMessage(QString::fromStdString(message));
        return false;
    };
    if (!stream.hasStream() || stream.live())
        return fail("Export annotations as COCO: open a stream with annotations first");
    const AnnotationsDocument& document = target.session.annotations();
    if (!document.loadProblem().isEmpty())
        return fail(document.loadProblem().toStdString());
    if (document.annotations().frames.empty())
        return fail("Export annotations as COCO: the stream has no annotated frame yet");
    const std::string spec = toLocalPath(stream.streamSpec());
    const std::string source = toLocalPath(document.path());
    const std::string out = toLocalPath(path);
    if (Status s = checkNotAnInput("Export annotations as COCO", out, {spec, source}); !s)
        return fail(s.error().message);
    CocoStream frames;
    frames.path = spec;
    for (std::size_t i = 0; i < stream.frameCount(); ++i)
        frames.frame_names.push_back(toLocalPath(stream.frameName(i)));
    frames.width = stream.info().width;
    frames.height = stream.info().height;
    frames.orientation = stream.orientation();
    auto json = cocoJson(document.annotations(), frames, document.kinds(), source);
    if (!json)
        return fail(json.error().message);
    if (Status s = writeFileAtomically(out, json.value()); !s)
        return fail(s.error().message);
    target.showMessage(QObject::tr("Exported the annotations of %1 frames to %2 as COCO")
                           .arg(document.annotations().frames.size())
                           .arg(path),
                       false);
    return true;
}

} // namespace fieldsight::ui
