// Rendering frames with their layers to PNG files.
#include "commands/render.h"

#include "ui/adapters/overlay_painter.h"
#include "visioncore/basics/atomic_file.h"
#include "visioncore/basics/json_text.h"
#include "visioncore/basics/output_guard.h"

#include <nlohmann/json.hpp>

#include <QBuffer>
#include <QImage>

#include <filesystem>

namespace fieldsight::cli {

Status prepareRenderFolder(const std::string& dir, const std::string& stream)
{
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec)
        return Error{dir + ": cannot create folder: " + ec.message()};
    // Marks the folder as a render, which a later render may replace (checkRenderFolder).
    const std::string marker =
        "{\"format\": \"fieldsight-render/1\", \"stream\": " + jsonText(nlohmann::json(stream)) +
        "}\n";
    return writeFileAtomically((std::filesystem::path(dir) / kRenderMarker).string(), marker);
}

Status renderFrame(const RenderOptions& options, const FrameResult& result, const Frame& frame,
                   const DebugCanvas& canvas)
{
    const auto it = options.truth.find(frameStem(result.name));
    const PerceptSet* truth = it == options.truth.end() ? nullptr : it->second;
    const std::vector<DebugDrawing> drawings =
        frameDrawings(*options.pipeline, options.layers, canvas, result.percepts, truth);
    std::vector<const DebugDrawing*> layers;
    for (const DebugDrawing& d : drawings)
        layers.push_back(&d);
    const QImage image = ui::renderOverlay(frame.ycbcr, layers, options.scale);

    QByteArray png;
    QBuffer buffer(&png);
    buffer.open(QIODevice::WriteOnly);
    if (!image.save(&buffer, "PNG"))
        return Error{options.dir + ": cannot encode the overlay of " + result.name};
    const std::string stem = std::filesystem::path(result.name).stem().string();
    return writeFileAtomically(options.dir + "/" + stem + ".png", png.constData(),
                               std::size_t(png.size()));
}

} // namespace fieldsight::cli
