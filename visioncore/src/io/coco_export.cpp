// Writing annotations as COCO JSON, kind by kind through their editable shapes (ShapeForm), so
// a new drawn kind is exported without a change here.
#include "visioncore/io/coco_export.h"

#include "visioncore/basics/json_text.h"
#include "visioncore/basics/message_text.h"

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

/// An axis-aligned box in continuous image coordinates (px from the top-left corner).
struct Span
{
    double x0, y0, x1, y1;
};

/// `span` clipped to the W x H image, at least 1 px wide and high and inside the image (an
/// object wholly outside it keeps a 1 px box at the nearest edge, so it is not lost).
Span clipped(Span span, int width, int height)
{
    const auto axis = [](double& lo, double& hi, double size) {
        lo = std::clamp(lo, 0.0, size);
        hi = std::clamp(hi, 0.0, size);
        if (hi - lo < 1) {
            hi = std::min(size, lo + 1);
            lo = std::max(0.0, hi - 1);
        }
    };
    axis(span.x0, span.x1, std::max(1, width));
    axis(span.y0, span.y1, std::max(1, height));
    return span;
}

/// COCO's [x, y, w, h] of `span`, tidied.
Json bbox(const Span& span)
{
    return Json::array(
        {tidy(span.x0), tidy(span.y0), tidy(span.x1 - span.x0), tidy(span.y1 - span.y0)});
}

/// The area of the disc at `c` of radius `r` inside [0, W] x [0, H]: π r² when it is all inside.
double discArea(PointF c, double r, int width, int height)
{
    if (r <= 0)
        return 0;
    if (c.x - r >= 0 && c.x + r <= width && c.y - r >= 0 && c.y + r <= height)
        return std::numbers::pi * r * r;
    // The chord's part inside the rows, integrated over the columns inside (midpoint rule; a
    // thousand steps is far finer than a pixel for any ball).
    const double x0 = std::max(0.0, c.x - r), x1 = std::min(double(width), c.x + r);
    if (x1 <= x0)
        return 0;
    constexpr int kSteps = 1000;
    const double dx = (x1 - x0) / kSteps;
    double area = 0;
    for (int k = 0; k < kSteps; ++k) {
        const double u = x0 + (k + 0.5) * dx - c.x;
        const double half = std::sqrt(std::max(0.0, r * r - u * u));
        area += std::max(0.0, std::min(double(height), c.y + half) - std::max(0.0, c.y - half));
    }
    return area * dx;
}

/// The COCO fields of one shape in a W x H image: bbox (clipped to the image, at least 1 px
/// each way), area and, by form, the exact geometry as annotated.
void addGeometry(ShapeForm form, const EditShape& shape, int width, int height, Json& out)
{
    if (form == ShapeForm::Circle) {
        const PointF c = shape.points.empty() ? PointF{} : shape.points.front();
        const double r = shape.radius;
        out["bbox"] = bbox(clipped({c.x - r, c.y - r, c.x + r, c.y + r}, width, height));
        out["area"] = tidy(discArea(c, r, width, height));
        out["circle"] = {c.x, c.y, r};
        return;
    }
    if (shape.points.empty()) {
        out["bbox"] = bbox(clipped({0, 0, 0, 0}, width, height));
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
        const Span box = clipped({x0, y0, x1 + 1, y1 + 1}, width, height);
        out["bbox"] = bbox(box);
        out["area"] = tidy((box.x1 - box.x0) * (box.y1 - box.y0));
        return;
    }
    out["bbox"] = bbox(clipped({x0, y0, x1, y1}, width, height));
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
        if (it == by_name.end()) {
            it = by_stem.find(frameStem(entry.first));
            if (it == by_stem.end())
                return Error{source + ": frame '" + messageText(entry.first) +
                             "' is annotated but " + stream.path + " has no such frame"};
        }
        // Two names of one frame are refused when the annotations are read.
        if (!frames.emplace(it->second, &entry).second)
            return Error{source + ": frames '" + messageText(frames.at(it->second)->first) +
                         "' and '" + messageText(entry.first) + "' are one frame of " +
                         stream.path};
    }

    // Written an image or an object a line into the one text, each as it is made: the whole
    // file is never held as a JSON tree (several times its text), nor copied.
    const Json info{{"description", "Fieldsight annotations of " + stream.path},
                    {"version", "fieldsight-coco/1"},
                    {"orientation", degrees(stream.orientation)}};
    std::string text = "{\n \"info\": " + jsonText(info) + ",\n \"images\": [";
    const char* separator = "\n  ";
    for (const auto& [index, entry] : frames) {
        const auto& [name, frame] = *entry;
        Json image{{"id", index + 1},
                   {"file_name", stream.frame_names[index]},
                   {"width", stream.width},
                   {"height", stream.height}};
        Json extra{{"annotation_name", name}, {"index", index}, {"done", frame.done}};
        if (!frame.reviewed.empty())
            extra["reviewed"] = frame.reviewed;
        image["fieldsight"] = std::move(extra);
        text += separator + jsonText(image);
        separator = ",\n  ";
    }
    text += "\n ],\n \"annotations\": [";
    separator = "\n  ";
    std::size_t object_count = 0;
    for (const auto& [index, entry] : frames) {
        const FrameAnnotation& frame = entry->second;
        for (std::size_t k = 0; k < drawn.size(); ++k) {
            const PerceptEntry* list = frame.truth.find(*drawn[k]);
            if (!list || !list->present())
                continue;
            const std::vector<EditShape> shapes = list->shapes();
            for (std::size_t i = 0; i < shapes.size(); ++i) {
                Json object{{"id", ++object_count},
                            {"image_id", index + 1},
                            {"category_id", k + 1},
                            {"iscrowd", 0},
                            {"segmentation", Json::array()}};
                addGeometry(drawn[k]->form, shapes[i], stream.width, stream.height, object);
                object["attributes"] = attributesOf(frame.flagsOf(drawn[k]->truth_key, i));
                text += separator + jsonText(object);
                separator = ",\n  ";
            }
        }
    }
    text += "\n ],\n \"categories\": [";
    for (std::size_t k = 0; k < categories.size(); ++k)
        text += (k ? ",\n  " : "\n  ") + jsonText(categories[k]);
    text += "\n ]\n}\n";
    return text;
}

} // namespace fieldsight
