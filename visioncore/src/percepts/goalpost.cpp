// Goalpost percepts in JSON and as a drawing.
#include "visioncore/percepts/goalpost.h"

#include "percepts/percept_json.h"

#include <algorithm>
#include <cmath>

namespace fieldsight {

using namespace percept_json;

void PerceptTraits<Goalpost>::toJson(const std::vector<Goalpost>& posts, PerceptNames names,
                                     OrderedJson& value)
{
    // Annotations (SPEC 5.2) hold only the box; the base is derived when they are read.
    const bool with_base = names == PerceptNames::Results;
    writeList(posts, value, [with_base](const Goalpost& g) {
        OrderedJson j{{"left", g.left}, {"right", g.right}, {"top", g.top}, {"bottom", g.bottom}};
        if (with_base) {
            j["base_x"] = px(g.base_x);
            j["base_y"] = px(g.base_y);
        }
        return j;
    });
}

std::optional<std::string> PerceptTraits<Goalpost>::fromJson(const Json& value, PerceptNames,
                                                             const std::string& where,
                                                             std::vector<Goalpost>& out)
{
    return readList(value, where, out, [](FieldReader& f) {
        Goalpost post;
        post.left = f.pixel("left");
        post.right = f.pixel("right");
        post.top = f.pixel("top");
        post.bottom = f.pixel("bottom");
        post.base_x = f.has("base_x") ? f.number("base_x") : (post.left + post.right) / 2.0;
        post.base_y = f.has("base_y") ? f.number("base_y") : double(post.bottom);
        return post;
    });
}

void PerceptTraits<Goalpost>::draw(const std::vector<Goalpost>& posts, Rgb ink, double width,
                                   DebugDrawing& out)
{
    for (const Goalpost& g : posts) {
        out.add({ShapeKind::Rect,
                 {{double(g.left), double(g.top)}, {double(g.right), double(g.bottom)}},
                 ink,
                 width,
                 false,
                 width});
        out.add({ShapeKind::Points, {{g.base_x, g.base_y}}, ink, 2 * width + 1, true, width});
    }
}

} // namespace fieldsight

namespace fieldsight {

EditShape PerceptTraits<Goalpost>::shapeOf(const Goalpost& p)
{
    return {{{double(p.left), double(p.top)}, {double(p.right), double(p.bottom)}}, 0};
}

Goalpost PerceptTraits<Goalpost>::fromShape(const EditShape& s)
{
    const Box box = boxOfShape(s);
    Goalpost post{box.left, box.right, box.top, box.bottom};
    post.base_x = (post.left + post.right) / 2.0;
    post.base_y = post.bottom;
    return post;
}

std::optional<double> PerceptTraits<Goalpost>::matchCost(const Goalpost& detected,
                                                         const Goalpost& truth, int /*width*/,
                                                         int height)
{
    const double centre_x = 0.5 * (truth.left + truth.right);
    const double base_distance = std::abs(detected.base_x - centre_x);
    if (base_distance > std::max(4.0, double(truth.right - truth.left + 1)))
        return std::nullopt;
    const double post_height = double(truth.bottom - truth.top + 1);
    const bool touches_bottom = truth.bottom >= height - 1;
    if (!touches_bottom &&
        std::abs(detected.bottom - truth.bottom) > std::max(6.0, 0.1 * post_height))
        return std::nullopt;
    return base_distance;
}

} // namespace fieldsight
