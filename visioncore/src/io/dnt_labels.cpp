// Reading the Dutch Nao Team's label files and turning their post feet and tops into goalpost
// boxes.
#include "visioncore/io/dnt_labels.h"

#include "visioncore/basics/atomic_file.h"
#include "visioncore/basics/message_text.h"
#include "visioncore/percepts/goalpost.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>
#include <optional>

namespace fieldsight {
namespace {

constexpr std::size_t kMaxLabelBytes = std::size_t(4) << 20;
/// The most post labels (feet and tops) one picture may have: a goal has two posts and a
/// picture shows at most two goals (the real files have at most 4). Pairing them looks at every
/// foot and top, so a bound per line keeps a file's import linear in its size.
constexpr std::size_t kMaxPostLabels = 64;
/// The labels the files use: a post's foot and top, and the three line crossings.
constexpr std::string_view kKnownLabels = "GULTX";

std::string_view trimmed(std::string_view s)
{
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t' || s.front() == '\r'))
        s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r'))
        s.remove_suffix(1);
    return s;
}

std::optional<int> integer(std::string_view s)
{
    int value = 0;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
    if (ec != std::errc() || end != s.data() + s.size())
        return std::nullopt;
    return value;
}

/// "G<125,68>" as a point, or nothing.
std::optional<DntPoint> point(std::string_view item)
{
    if (item.size() < 6 || item[0] < 'A' || item[0] > 'Z' || item[1] != '<' || item.back() != '>')
        return std::nullopt;
    const std::string_view inside = item.substr(2, item.size() - 3);
    const auto comma = inside.find(',');
    if (comma == std::string_view::npos)
        return std::nullopt;
    const auto x = integer(trimmed(inside.substr(0, comma)));
    const auto y = integer(trimmed(inside.substr(comma + 1)));
    if (!x || !y)
        return std::nullopt;
    return DntPoint{item[0], *x, *y};
}

/// One post: its foot and top as labelled (either may be missing, not both).
struct Post
{
    std::optional<DntPoint> foot;
    std::optional<DntPoint> top;
};

/// Each foot with the top above it nearest in x (greedy, nearest first), then the tops left.
std::vector<Post> postsOf(const std::vector<DntPoint>& points)
{
    std::vector<DntPoint> feet, tops;
    for (const DntPoint& p : points) {
        if (p.label == 'G')
            feet.push_back(p);
        else if (p.label == 'U')
            tops.push_back(p);
    }
    struct Pair
    {
        int dx;
        std::size_t foot, top;
    };
    std::vector<Pair> pairs;
    for (std::size_t f = 0; f < feet.size(); ++f)
        for (std::size_t t = 0; t < tops.size(); ++t) {
            const int height = feet[f].y - tops[t].y;
            const int dx = std::abs(feet[f].x - tops[t].x);
            if (height > 0 && dx <= std::max(8.0, 0.25 * height))
                pairs.push_back({dx, f, t});
        }
    std::sort(pairs.begin(), pairs.end(), [](const Pair& a, const Pair& b) {
        return std::tie(a.dx, a.foot, a.top) < std::tie(b.dx, b.foot, b.top);
    });
    std::vector<std::optional<std::size_t>> top_of(feet.size());
    std::vector<bool> top_used(tops.size(), false);
    for (const Pair& p : pairs) {
        if (top_of[p.foot] || top_used[p.top])
            continue;
        top_of[p.foot] = p.top;
        top_used[p.top] = true;
    }
    std::vector<Post> posts;
    for (std::size_t f = 0; f < feet.size(); ++f)
        posts.push_back({feet[f], top_of[f] ? std::optional(tops[*top_of[f]]) : std::nullopt});
    for (std::size_t t = 0; t < tops.size(); ++t)
        if (!top_used[t])
            posts.push_back({std::nullopt, tops[t]});
    return posts;
}

/// The boxes of one picture's posts (docs/formats.md says how each is sized).
std::vector<Goalpost> boxesOf(const std::vector<Post>& posts, int width, int height,
                              const DntPostModel& model)
{
    // A post's own height sizes it; else the two feet's distance; else a sized post of the
    // same picture (about as far away); else the default. (Negative: not known.)
    std::vector<double> widths(posts.size(), -1);
    double picture_width = -1;
    for (std::size_t i = 0; i < posts.size(); ++i)
        if (posts[i].foot && posts[i].top) {
            widths[i] = (posts[i].foot->y - posts[i].top->y + 1) / model.height_per_width;
            if (picture_width < 0)
                picture_width = widths[i];
        }
    std::vector<int> feet;
    for (const Post& p : posts)
        if (p.foot)
            feet.push_back(p.foot->x);
    const double from_feet =
        feet.size() == 2 ? std::abs(feet[0] - feet[1]) / model.separation_per_width : -1;

    std::vector<Goalpost> boxes;
    for (std::size_t i = 0; i < posts.size(); ++i) {
        const Post& p = posts[i];
        double w = widths[i];
        if (w < 0)
            w = p.foot && from_feet >= 0 ? from_feet : picture_width;
        if (w < 0)
            w = model.default_width;
        const int post_width = std::max(3, int(std::lround(w)));
        const int centre = p.foot ? p.foot->x : p.top->x;
        Goalpost box;
        box.left = std::clamp(centre - (post_width - 1) / 2, 0, width - 1);
        box.right = std::clamp(centre - (post_width - 1) / 2 + post_width - 1, 0, width - 1);
        // A post without a labelled foot reaches below the picture.
        box.bottom = p.foot ? std::clamp(p.foot->y, 0, height - 1) : height - 1;
        box.top = p.top ? std::clamp(p.top->y, 0, box.bottom)
                        : std::max(0, box.bottom + 1 -
                                          int(std::lround(post_width * model.height_per_width)));
        box.base_x = (box.left + box.right) / 2.0;
        box.base_y = box.bottom;
        boxes.push_back(box);
    }
    std::sort(boxes.begin(), boxes.end(),
              [](const Goalpost& a, const Goalpost& b) { return a.left < b.left; });
    return boxes;
}

} // namespace

std::string DntPicture::number() const
{
    return name.substr(0, name.find(' '));
}

Result<std::vector<DntPicture>> parseDntLabels(const std::string& text, const std::string& source)
{
    std::vector<DntPicture> pictures;
    std::size_t line_number = 0;
    // A UTF-8 byte order mark (an editor on Windows writes one) is no part of the first line.
    std::size_t start = text.starts_with("\xEF\xBB\xBF") ? 3 : 0;
    while (start < text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string::npos)
            end = text.size();
        const std::string_view line = trimmed(std::string_view(text).substr(start, end - start));
        start = end + 1;
        ++line_number;
        if (line.empty())
            continue;
        const std::string where = source + ": line " + std::to_string(line_number) + ": ";
        std::size_t post_labels = 0;
        const auto open = line.rfind('[');
        if (line.size() < 4 || line.front() != '\'' || line.back() != '\'' ||
            open == std::string_view::npos || line[line.size() - 2] != ']')
            return Error{where + "expected '<picture name> [<labels>]', not '" + messageText(line) +
                         "'"};
        DntPicture picture;
        picture.line = line_number;
        picture.name = std::string(trimmed(line.substr(1, open - 1)));
        if (picture.name.empty())
            return Error{where + "no picture name"};
        std::string_view labels = line.substr(open + 1, line.size() - open - 3);
        while (!labels.empty()) {
            const auto semicolon = labels.find(';');
            const std::string_view item = trimmed(labels.substr(0, semicolon));
            labels = semicolon == std::string_view::npos ? std::string_view()
                                                         : labels.substr(semicolon + 1);
            if (item.empty())
                continue;
            const auto p = point(item);
            if (!p)
                return Error{where + "'" + messageText(item) +
                             "' is not a label such as G<125,68>"};
            if (kKnownLabels.find(p->label) == std::string_view::npos)
                return Error{where + "'" + messageText(item) + "': unknown label '" +
                             std::string(1, p->label) +
                             "' (G a post's foot, U its top; L, T, X line crossings)"};
            if ((p->label == 'G' || p->label == 'U') && ++post_labels > kMaxPostLabels)
                return Error{where + "more than " + std::to_string(kMaxPostLabels) +
                             " post labels (G, U) in one picture; a picture shows at most two "
                             "goals"};
            picture.points.push_back(*p);
        }
        pictures.push_back(std::move(picture));
    }
    return pictures;
}

Result<std::vector<DntPicture>> loadDntLabels(const std::string& path)
{
    auto text = readWholeFile(path, kMaxLabelBytes, "label file");
    if (!text)
        return text.error();
    return parseDntLabels(text.value(), path);
}

Result<DntImport> importDntGoalposts(const std::vector<DntPicture>& pictures,
                                     const StreamReader& reader, const std::string& source,
                                     const DntPostModel& model)
{
    std::map<std::string, std::string> by_name, by_stem;
    for (std::size_t i = 0; i < reader.info().frame_count; ++i) {
        by_name.emplace(reader.frameName(i), reader.frameName(i));
        by_stem.emplace(frameStem(reader.frameName(i)), reader.frameName(i));
    }
    DntImport out;
    std::map<std::string, std::size_t> labelled; ///< frames labelled, by name: their line
    const std::string key(perceptKind<Goalpost>().truth_key);
    for (const DntPicture& picture : pictures) {
        auto it = by_name.find(picture.name);
        if (it == by_name.end()) {
            it = by_stem.find(picture.number());
            if (it == by_stem.end()) {
                out.not_in_stream.push_back(picture.name);
                continue;
            }
        }
        if (const auto [first, fresh] = labelled.emplace(it->second, picture.line); !fresh)
            return Error{source + ": line " + std::to_string(picture.line) + ": '" +
                         messageText(picture.name) + "' is frame " + messageText(it->second) +
                         ", which line " + std::to_string(first->second) + " labels already"};
        FrameAnnotation frame;
        frame.reviewed.insert(key);
        std::vector<Goalpost>& posts = frame.truth.output<Goalpost>();
        posts = boxesOf(postsOf(picture.points), reader.info().width, reader.info().height, model);
        out.posts += posts.size();
        ++out.pictures;
        out.annotations.frames[it->second] = std::move(frame);
    }
    if (out.pictures == 0)
        return Error{source + ": none of its " + std::to_string(pictures.size()) +
                     " pictures is a frame of " + reader.info().path};
    return out;
}

} // namespace fieldsight
