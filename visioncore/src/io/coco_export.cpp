// Writing annotations as COCO JSON, kind by kind through their editable shapes (ShapeForm), so
// a new drawn kind is exported without a change here.
#include "visioncore/io/coco_export.h"

#include "visioncore/basics/json_text.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

namespace fieldsight {
namespace {

using Json = nlohmann::ordered_json;

const char* formName(ShapeForm form)
{
    switch (form) {
    case ShapeForm::Circle:
        return "circle";
    case ShapeForm::Box:
        return "box";
    case ShapeForm::Polyline:
        return "polyline";
    case ShapeForm::Segment:
        return "segment";
    case ShapeForm::None:
        break;
    }
    return "none";
}

/// `v` to 6 decimals, so a width of 17.42 is not written as 17.419999999999995.
double tidy(double v)
{
    return std::round(v * 1e6) / 1e6;
}

/// [x, y, w, h], tidied.
Json bbox(double x, double y, double w, double h)
{
    return Json::array({tidy(x), tidy(y), tidy(w), tidy(h)});
}

/// The COCO fields of one shape: bbox, area and, by form, the exact geometry.
void addGeometry(ShapeForm form, const EditShape& shape, Json& out)
{
    if (form == ShapeForm::Circle) {
        const PointF c = shape.points.empty() ? PointF{} : shape.points.front();
        const double r = shape.radius;
        out["bbox"] = bbox(c.x - r, c.y - r, 2 * r, 2 * r);
        out["area"] = tidy(std::numbers::pi * r * r);
        out["circle"] = {c.x, c.y, r};
        return;
    }
    if (shape.points.empty()) {
        out["bbox"] = bbox(0, 0, 0, 0);
        out["area"] = 0;
        return;
    }
    double x0 = shape.points.front().x, x1 = x0, y0 = shape.points.front().y, y1 = y0;
    for (const PointF& p : shape.points) {
        x0 = std::min(x0, p.x);
        x1 = std::max(x1, p.x);
        y0 = std::min(y0, p.y);
        y1 = std::max(y1, p.y);
    }
    if (form == ShapeForm::Box) {
        // Inclusive pixel rows and columns: the box covers [left, right + 1) x [top, bottom + 1).
        out["bbox"] = bbox(x0, y0, x1 - x0 + 1, y1 - y0 + 1);
        out["area"] = tidy((x1 - x0 + 1) * (y1 - y0 + 1));
        return;
    }
    out["bbox"] = bbox(x0, y0, x1 - x0, y1 - y0);
    out["area"] = 0;
    Json line = Json::array();
    for (const PointF& p : shape.points) {
        line.push_back(p.x);
        line.push_back(p.y);
    }
    out["polyline"] = std::move(line);
}

Json attributesOf(const ObjectFlags& f)
{
    // "occluded" is what CVAT and Datumaro read; "concealed" is Fieldsight's own name.
    Json a{{"occluded", f.concealed}, {"concealed", f.concealed}};
    if (f.track != 0) {
        a["track_id"] = f.track;
        a["keyframe"] = f.keyframe;
    }
    if (f.interpolated)
        a["interpolated"] = true;
    return a;
}

} // namespace

CocoStream CocoStream::of(const StreamReader& reader)
{
    CocoStream s;
    s.path = reader.info().path;
    for (std::size_t i = 0; i < reader.info().frame_count; ++i)
        s.frame_names.push_back(reader.frameName(i));
    s.width = reader.info().width;
    s.height = reader.info().height;
    s.orientation = reader.info().orientation;
    return s;
}

Result<std::string> cocoJson(const Annotations& annotations, const CocoStream& stream,
                             const std::vector<const PerceptKind*>& kinds,
                             const std::string& source)
{
    std::map<std::string, std::size_t> by_name, by_stem;
    for (std::size_t i = 0; i < stream.frame_names.size(); ++i) {
        by_name.emplace(stream.frame_names[i], i);
        by_stem.emplace(frameStem(stream.frame_names[i]), i);
    }

    Json categories = Json::array();
    std::vector<const PerceptKind*> drawn;
    for (const PerceptKind* kind : kinds) {
        if (kind->form == ShapeForm::None)
            continue;
        drawn.push_back(kind);
        categories.push_back({{"id", drawn.size()},
                              {"name", std::string(kind->truth_key)},
                              {"supercategory", "fieldsight"},
                              {"shape", formName(kind->form)}});
    }

    // Images by stream index (their id is the index + 1, the same whatever else is annotated).
    std::map<std::size_t, const std::pair<const std::string, FrameAnnotation>*> frames;
    for (const auto& entry : annotations.frames) {
        auto it = by_name.find(entry.first);
        if (it == by_name.end())
            it = by_stem.find(frameStem(entry.first));
        if (it == by_stem.end())
            return Error{source + ": frame '" + entry.first + "' is annotated but " + stream.path +
                         " has no such frame"};
        frames.emplace(it->second, &entry);
    }

    Json images = Json::array();
    Json objects = Json::array();
    for (const auto& [index, entry] : frames) {
        const auto& [name, frame] = *entry;
        const std::size_t image_id = index + 1;
        Json image{{"id", image_id},
                   {"file_name", stream.frame_names[index]},
                   {"width", stream.width},
                   {"height", stream.height}};
        Json extra{{"annotation_name", name}, {"index", index}, {"done", frame.done}};
        if (!frame.reviewed.empty())
            extra["reviewed"] = frame.reviewed;
        image["fieldsight"] = std::move(extra);
        images.push_back(std::move(image));
        for (std::size_t k = 0; k < drawn.size(); ++k) {
            const PerceptEntry* list = frame.truth.find(*drawn[k]);
            if (!list || !list->present())
                continue;
            const std::vector<EditShape> shapes = list->shapes();
            for (std::size_t i = 0; i < shapes.size(); ++i) {
                Json object{{"id", objects.size() + 1},
                            {"image_id", image_id},
                            {"category_id", k + 1},
                            {"iscrowd", 0},
                            {"segmentation", Json::array()}};
                addGeometry(drawn[k]->form, shapes[i], object);
                object["attributes"] = attributesOf(frame.flagsOf(drawn[k]->truth_key, i));
                objects.push_back(std::move(object));
            }
        }
    }

    Json root;
    root["info"] = {{"description", "Fieldsight annotations of " + stream.path},
                    {"version", "fieldsight-coco/1"},
                    {"orientation", degrees(stream.orientation)}};
    root["images"] = std::move(images);
    root["annotations"] = std::move(objects);
    root["categories"] = std::move(categories);
    return jsonText(root, 1) + "\n";
}

} // namespace fieldsight
