// Ground-truth annotation files (SPEC §5.2): strict reading, atomic writing.
#include "visioncore/annotations.h"

#include "visioncore/atomic_file.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <optional>

namespace fieldsight {

namespace {

constexpr const char* kFormat = "fieldsight-annotations/1";

using Json = nlohmann::json;
using OrderedJson = nlohmann::ordered_json;

/// Reads fields of one JSON object, remembering the first problem as "where.key must be ...".
class FieldReader
{
public:
    FieldReader(const Json& object, std::string where, std::optional<std::string>& problem)
        : m_object(object), m_where(std::move(where)), m_problem(problem)
    {
    }

    double number(const char* key)
    {
        const auto it = m_object.find(key);
        if (it == m_object.end() || !it->is_number()) {
            fail(key, "a number");
            return 0;
        }
        return it->get<double>();
    }
    /// A pixel index: any JSON number, rounded to the nearest integer.
    int pixel(const char* key) { return int(std::lround(number(key))); }

private:
    void fail(const char* key, const char* expected)
    {
        if (!m_problem)
            m_problem = m_where + "." + key + " must be " + expected;
    }

    const Json& m_object;
    std::string m_where;
    std::optional<std::string>& m_problem;
};

/// Calls `each(element, where)` for every element of the optional array `key`.
template <class Each>
void forEachIn(const Json& frame, const char* key, const std::string& where,
               std::optional<std::string>& problem, Each each)
{
    const auto it = frame.find(key);
    if (it == frame.end() || problem)
        return;
    if (!it->is_array()) {
        problem = where + "." + key + " must be an array";
        return;
    }
    for (std::size_t i = 0; i < it->size() && !problem; ++i) {
        const std::string item = where + "." + key + "[" + std::to_string(i) + "]";
        each((*it)[i], item);
    }
}

std::optional<std::string> readFrame(const Json& json, const std::string& where,
                                     FrameAnnotation& out)
{
    std::optional<std::string> problem;
    if (!json.is_object())
        return where + " must be an object";
    if (const auto done = json.find("done"); done != json.end()) {
        if (!done->is_boolean())
            return where + ".done must be true or false";
        out.done = done->get<bool>();
    }
    auto object = [&](const Json& item, const std::string& item_where) {
        if (!item.is_object())
            problem = item_where + " must be an object";
        return item.is_object();
    };
    forEachIn(json, "balls", where, problem, [&](const Json& item, const std::string& w) {
        if (!object(item, w))
            return;
        FieldReader f(item, w, problem);
        out.balls.push_back(Ball{f.number("x"), f.number("y"), f.number("radius")});
    });
    forEachIn(json, "goalposts", where, problem, [&](const Json& item, const std::string& w) {
        if (!object(item, w))
            return;
        FieldReader f(item, w, problem);
        Goalpost post;
        post.left = f.pixel("left");
        post.right = f.pixel("right");
        post.top = f.pixel("top");
        post.bottom = f.pixel("bottom");
        post.base_x = (post.left + post.right) / 2.0;
        post.base_y = post.bottom;
        out.goalposts.push_back(post);
    });
    forEachIn(json, "obstacles", where, problem, [&](const Json& item, const std::string& w) {
        if (!object(item, w))
            return;
        FieldReader f(item, w, problem);
        out.obstacles.push_back(
            Obstacle{f.pixel("left"), f.pixel("right"), f.pixel("top"), f.pixel("bottom")});
    });
    forEachIn(json, "field_boundary", where, problem, [&](const Json& item, const std::string& w) {
        if (!item.is_array() || item.size() != 2 || !item[0].is_number() || !item[1].is_number()) {
            problem = w + " must be [x, y]";
            return;
        }
        out.field_boundary.push_back(PointF{item[0].get<double>(), item[1].get<double>()});
    });
    forEachIn(json, "field_lines", where, problem, [&](const Json& item, const std::string& w) {
        if (!object(item, w))
            return;
        FieldReader f(item, w, problem);
        out.field_lines.push_back(
            FieldLine{f.number("x1"), f.number("y1"), f.number("x2"), f.number("y2")});
    });
    return problem;
}

} // namespace

Result<Annotations> Annotations::fromJson(const std::string& text, const std::string& source)
{
    const Json root = Json::parse(text, nullptr, false);
    if (root.is_discarded())
        return Error{source + ": not valid JSON"};
    if (!root.is_object())
        return Error{source + ": expected a JSON object at the top level"};
    const auto format = root.find("format");
    if (format == root.end() || !format->is_string())
        return Error{source + ": missing \"format\": \"" + kFormat + "\""};
    if (format->get<std::string>() != kFormat)
        return Error{source + ": unsupported format \"" + format->get<std::string>() +
                     "\" (expected \"" + kFormat + "\")"};

    Annotations annotations;
    const auto frames = root.find("frames");
    if (frames == root.end())
        return annotations;
    if (!frames->is_object())
        return Error{source + ": \"frames\" must be an object keyed by frame name"};
    for (const auto& [name, json] : frames->items()) {
        FrameAnnotation frame;
        if (auto problem = readFrame(json, "frames[\"" + name + "\"]", frame))
            return Error{source + ": " + *problem};
        annotations.frames.emplace(name, std::move(frame));
    }
    return annotations;
}

Result<Annotations> Annotations::load(const std::string& path)
{
    auto text = readWholeFile(path);
    if (!text)
        return text.error();
    return fromJson(text.value(), path);
}

std::string Annotations::toJson() const
{
    OrderedJson frames_json = OrderedJson::object();
    for (const auto& [name, frame] : frames) {
        OrderedJson out;
        out["done"] = frame.done;
        // Empty lists are left out: for a done frame absent and empty mean the same.
        if (!frame.balls.empty()) {
            OrderedJson& list = out["balls"] = OrderedJson::array();
            for (const Ball& b : frame.balls)
                list.push_back({{"x", b.x}, {"y", b.y}, {"radius", b.radius}});
        }
        if (!frame.goalposts.empty()) {
            OrderedJson& list = out["goalposts"] = OrderedJson::array();
            for (const Goalpost& g : frame.goalposts)
                list.push_back(
                    {{"left", g.left}, {"right", g.right}, {"top", g.top}, {"bottom", g.bottom}});
        }
        if (!frame.obstacles.empty()) {
            OrderedJson& list = out["obstacles"] = OrderedJson::array();
            for (const Obstacle& o : frame.obstacles)
                list.push_back(
                    {{"left", o.left}, {"right", o.right}, {"top", o.top}, {"bottom", o.bottom}});
        }
        if (!frame.field_boundary.empty()) {
            OrderedJson& list = out["field_boundary"] = OrderedJson::array();
            for (const PointF& p : frame.field_boundary)
                list.push_back(OrderedJson::array({p.x, p.y}));
        }
        if (!frame.field_lines.empty()) {
            OrderedJson& list = out["field_lines"] = OrderedJson::array();
            for (const FieldLine& l : frame.field_lines)
                list.push_back({{"x1", l.x1}, {"y1", l.y1}, {"x2", l.x2}, {"y2", l.y2}});
        }
        frames_json[name] = std::move(out);
    }
    OrderedJson root;
    root["format"] = kFormat;
    root["frames"] = std::move(frames_json);
    return root.dump(1) + "\n";
}

Status Annotations::save(const std::string& path) const
{
    return writeFileAtomically(path, toJson());
}

} // namespace fieldsight
