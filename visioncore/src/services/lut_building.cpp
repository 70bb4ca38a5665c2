// Building a colour LUT from samples: the samples file, samples from annotations, votes and
// their smoothing.
#include "visioncore/services/lut_building.h"

#include "visioncore/basics/json_text.h"
#include "basics/json_format.h"
#include "services/polygon_fill.h"

#include "visioncore/basics/atomic_file.h"
#include "visioncore/basics/message_text.h"
#include "visioncore/percepts/ball.h"
#include "visioncore/percepts/field_boundary.h"
#include "visioncore/percepts/field_line.h"
#include "visioncore/percepts/goalpost.h"
#include "visioncore/percepts/obstacle.h"

#include <nlohmann/json.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <numbers>

namespace fieldsight {

namespace {

using Json = nlohmann::json;
using OrderedJson = nlohmann::ordered_json;

constexpr int kMaxSmoothing = 8;          ///< cells; wider only blurs the classes together
constexpr int kMaxCoordinate = 1'000'000; ///< px, a sanity bound on polygon vertices
constexpr std::uint8_t kNoVote = 255;     ///< label of a pixel no sample covers
constexpr std::uint8_t kHole = 254;       ///< label of a pixel in an excluded region
constexpr int kDiscVertices = 32;

std::string sampleWhere(std::size_t i)
{
    return "samples[" + std::to_string(i) + "]";
}

Result<LutSample> sampleFromJson(const Json& json, const std::string& where)
{
    if (!json.is_object())
        return Error{where + " must be an object"};
    LutSample sample;
    const auto frame = json.find("frame");
    if (frame == json.end() || !frame->is_string() || frame->get<std::string>().empty())
        return Error{where + ".frame must be a frame's file name"};
    sample.frame = frame->get<std::string>();
    // The same rule as the annotations': "../lab2/frame_000000.png" is no frame of this stream.
    if (auto problem = frameNameProblem(sample.frame))
        return Error{where + ".frame \"" + messageText(sample.frame) + "\": the frame name " +
                     *problem + "; a frame is named by its file name alone"};
    if (const auto exclude = json.find("exclude"); exclude != json.end()) {
        if (!exclude->is_boolean())
            return Error{where + ".exclude must be true or false"};
        sample.exclude = exclude->get<bool>();
    }
    const auto colour = json.find("colour");
    if (colour != json.end()) {
        if (!colour->is_string())
            return Error{where + ".colour must be a colour class name"};
        const auto parsed = colourFromName(colour->get<std::string>());
        if (!parsed)
            return Error{where + ".colour: unknown colour class \"" +
                         messageText(colour->get<std::string>()) + "\""};
        sample.colour = *parsed;
    } else if (!sample.exclude) {
        return Error{where + ": missing \"colour\" (or \"exclude\": true)"};
    }
    const auto polygon = json.find("polygon");
    if (polygon == json.end() || !polygon->is_array())
        return Error{where + ".polygon must be a list of [x, y] points"};
    for (const Json& point : *polygon) {
        if (!point.is_array() || point.size() != 2 || !point[0].is_number_integer() ||
            !point[1].is_number_integer())
            return Error{where + ".polygon: every point must be [x, y] in whole pixels"};
        const auto x = point[0].get<long long>();
        const auto y = point[1].get<long long>();
        if (std::abs(x) > kMaxCoordinate || std::abs(y) > kMaxCoordinate)
            return Error{where + ".polygon: point [" + std::to_string(x) + ", " +
                         std::to_string(y) + "] is far outside any image"};
        sample.polygon.emplace_back(int(x), int(y));
    }
    if (sample.polygon.size() < 3)
        return Error{where + ".polygon has " + std::to_string(sample.polygon.size()) +
                     " points; a region needs at least 3"};
    sample.unknown = unknownKeys(json, {"frame", "exclude", "colour", "polygon"});
    return sample;
}

cv::Point rounded(double x, double y)
{
    return {int(std::lround(x)), int(std::lround(y))};
}

std::vector<cv::Point> disc(double cx, double cy, double radius)
{
    std::vector<cv::Point> polygon;
    for (int i = 0; i < kDiscVertices; ++i) {
        const double a = 2 * std::numbers::pi * i / kDiscVertices;
        polygon.push_back(rounded(cx + radius * std::cos(a), cy + radius * std::sin(a)));
    }
    return polygon;
}

/// The inclusive box grown by `grow` px on every side (negative shrinks it, never below one
/// column or row through its middle).
std::vector<cv::Point> box(int left, int top, int right, int bottom, int grow)
{
    int l = left - grow, r = right + grow, t = top - grow, b = bottom + grow;
    if (l > r)
        l = r = (left + right) / 2;
    if (t > b)
        t = b = (top + bottom) / 2;
    return {{l, t}, {r, t}, {r, b}, {l, b}};
}

std::vector<cv::Point> strip(const FieldLine& line, double half_width)
{
    const double dx = line.x2 - line.x1, dy = line.y2 - line.y1;
    const double length = std::hypot(dx, dy);
    const double nx = length > 0 ? -dy / length * half_width : 0;
    const double ny = length > 0 ? dx / length * half_width : half_width;
    return {rounded(line.x1 + nx, line.y1 + ny), rounded(line.x2 + nx, line.y2 + ny),
            rounded(line.x2 - nx, line.y2 - ny), rounded(line.x1 - nx, line.y1 - ny)};
}

/// The boundary from x = 0 to x = width-1 (held constant beyond its ends), moved down by `dy`.
std::vector<cv::Point> boundaryPoints(const std::vector<PointF>& boundary, int width, double dy)
{
    std::vector<cv::Point> points;
    points.push_back(rounded(0, boundary.front().y + dy));
    for (const PointF& p : boundary)
        if (p.x > 0 && p.x < width - 1)
            points.push_back(rounded(p.x, p.y + dy));
    points.push_back(rounded(width - 1, boundary.back().y + dy));
    return points;
}

using Weights = std::array<float, kColourCount>;

/// The votes spread with weight 2^-|d| along each channel in turn (the kernel is separable).
std::unordered_map<std::uint32_t, Weights>
smoothedWeights(const std::unordered_map<std::uint32_t, LutVotes::Counts>& votes, int smoothing)
{
    std::unordered_map<std::uint32_t, Weights> weights;
    weights.reserve(votes.size());
    for (const auto& [cell, counts] : votes) {
        Weights& w = weights[cell];
        for (int c = 0; c < kColourCount; ++c)
            w[std::size_t(c)] = float(counts[std::size_t(c)]);
    }
    smoothing = std::clamp(smoothing, 0, kMaxSmoothing);
    for (const int shift : {14, 7, 0}) {
        if (smoothing == 0)
            break;
        std::unordered_map<std::uint32_t, Weights> spread;
        spread.reserve(weights.size() * std::size_t(2 * smoothing + 1));
        for (const auto& [cell, w] : weights) {
            const int coordinate = int(cell >> shift) & 127;
            const std::uint32_t rest = cell & ~(std::uint32_t(127) << shift);
            for (int d = -smoothing; d <= smoothing; ++d) {
                const int c = coordinate + d;
                if (c < 0 || c > 127)
                    continue;
                const float k = std::ldexp(1.0f, -std::abs(d));
                Weights& out = spread[rest | (std::uint32_t(c) << shift)];
                for (std::size_t i = 0; i < w.size(); ++i)
                    out[i] += k * w[i];
            }
        }
        weights = std::move(spread);
    }
    return weights;
}

struct Ranking
{
    int winner = 0;
    int runner_up = 0;
    float winner_weight = 0;
    float runner_up_weight = 0;
};

Ranking rank(const Weights& w)
{
    Ranking r;
    r.runner_up = -1;
    for (int c = 0; c < kColourCount; ++c) {
        const float v = w[std::size_t(c)];
        if (v > r.winner_weight) {
            r.runner_up = r.winner;
            r.runner_up_weight = r.winner_weight;
            r.winner = c;
            r.winner_weight = v;
        } else if (v > r.runner_up_weight) {
            r.runner_up = c;
            r.runner_up_weight = v;
        }
    }
    if (r.runner_up < 0)
        r.runner_up = 0;
    return r;
}

bool isPair(const Ranking& r, Colour a, Colour b)
{
    return (r.winner == int(a) && r.runner_up == int(b)) ||
           (r.winner == int(b) && r.runner_up == int(a));
}

} // namespace

std::string defaultLutSamplesPath(const std::string& stream)
{
    return besideStream(stream, "lut_samples.json");
}

Result<LutSamples> lutSamplesFromJson(const std::string& text, const std::string& source)
{
    // Each sample is read as soon as the parser has it and then dropped (parseJsonMembers).
    LutSamples out;
    std::optional<Error> problem;
    auto parsed = parseJsonMembers(text, source, "samples",
                                   [&](const std::string&, std::size_t i, const Json& json) {
                                       if (problem)
                                           return;
                                       auto sample = sampleFromJson(json, sampleWhere(i));
                                       if (!sample)
                                           problem = Error{source + ": " + sample.error().message};
                                       else
                                           out.samples.push_back(std::move(sample).value());
                                   });
    if (!parsed)
        return parsed.error();
    const Json& root = parsed.value();
    if (auto bad = formatProblem(root, source, kLutSamplesFormat))
        return *bad;
    if (const auto smoothing = root.find("smoothing"); smoothing != root.end()) {
        if (!smoothing->is_number_integer() || smoothing->get<long long>() < 0 ||
            smoothing->get<long long>() > kMaxSmoothing)
            return Error{source + ": \"smoothing\" must be a whole number of cells, 0 to " +
                         std::to_string(kMaxSmoothing)};
        out.smoothing = smoothing->get<int>();
    }
    const auto samples = root.find("samples");
    if (samples == root.end() || !samples->is_array())
        return Error{source + ": \"samples\" must be a list of samples"};
    if (problem)
        return *problem;
    out.unknown = unknownKeys(root, {"format", "smoothing", "samples"});
    return out;
}

std::size_t maxLutSamplesBytes(std::size_t frames)
{
    return (std::size_t(16) << 20) + frames * 4096;
}

Result<LutSamples> loadLutSamples(const std::string& path, std::size_t frames)
{
    return readingWithinMemory(path, [&]() -> Result<LutSamples> {
        auto text = readWholeFile(path, maxLutSamplesBytes(frames),
                                  frames ? "LUT samples of " + std::to_string(frames) + " frames"
                                         : std::string("LUT samples"));
        if (!text)
            return text.error();
        return lutSamplesFromJson(text.value(), path);
    });
}

std::string lutSamplesToJson(const LutSamples& samples)
{
    // One sample a line: a stream's samples stay readable and diff well.
    std::string text = "{\n \"format\": \"" + std::string(kLutSamplesFormat) +
                       "\",\n \"smoothing\": " + std::to_string(samples.smoothing) +
                       ",\n \"samples\": [";
    for (std::size_t i = 0; i < samples.samples.size(); ++i) {
        const LutSample& s = samples.samples[i];
        OrderedJson json;
        json["frame"] = s.frame;
        if (s.exclude)
            json["exclude"] = true;
        else
            json["colour"] = colourName(s.colour);
        OrderedJson polygon = OrderedJson::array();
        for (const cv::Point& p : s.polygon)
            polygon.push_back({p.x, p.y});
        json["polygon"] = std::move(polygon);
        addUnknownKeys(s.unknown, json);
        text += (i == 0 ? "\n  " : ",\n  ") + jsonText(json);
    }
    text += samples.samples.empty() ? "]" : "\n ]";
    if (!samples.unknown.empty()) {
        // The top level's keys this version does not read, after its own.
        const std::string kept = jsonText(OrderedJson::parse(samples.unknown), 1);
        if (kept.size() > 4) // "{\n ... \n}": its keys, one a line, without the braces
            text += ",\n" + kept.substr(2, kept.size() - 4);
    }
    return text + "\n}\n";
}

Status saveLutSamples(const std::string& path, const LutSamples& samples)
{
    return writeFileAtomically(path, lutSamplesToJson(samples));
}

std::vector<LutSample> samplesFromAnnotations(const Annotations& annotations, cv::Size frame_size,
                                              const AnnotationSampleRules& rules)
{
    std::vector<LutSample> out;
    const double shrink = std::max(0.0, rules.shrink_px);
    const int grow = int(std::lround(shrink));
    for (const auto& entry : annotations.frames) {
        const std::string& name = entry.first; // not a structured binding: captured below
        const auto& frame = entry.second;
        if (!frame.done)
            continue;
        auto add = [&](Colour colour, std::vector<cv::Point> polygon, bool exclude = false) {
            out.push_back({name, colour, std::move(polygon), exclude});
        };
        const PerceptSet& truth = frame.truth;
        const std::vector<PointF>& boundary = boundaryOf(truth);
        const int w = frame_size.width, h = frame_size.height;
        if (!boundary.empty()) {
            if (rules.background) {
                std::vector<cv::Point> sky = boundaryPoints(boundary, w, -shrink);
                std::reverse(sky.begin(), sky.end());
                sky.insert(sky.begin(), {{0, 0}, {w - 1, 0}});
                add(Colour::Unclassified, std::move(sky));
            }
            std::vector<cv::Point> field = boundaryPoints(boundary, w, shrink);
            field.insert(field.end(), {{w - 1, h - 1}, {0, h - 1}});
            add(Colour::Green, std::move(field));
        }
        if (rules.background) {
            // The crossbar is goal-coloured but not annotated: the rows around a post's top
            // (when it is in view) are left out of the background.
            for (const Goalpost& p : truth.list<Goalpost>()) {
                if (p.top <= 0)
                    continue;
                const int band = 2 * (p.right - p.left + 1) + grow;
                add(Colour::Unclassified, box(0, p.top - band, w - 1, p.top + band, 0), true);
            }
        }
        // A concealed object (partly hidden, blurred) votes for nothing: its outline holds the
        // pixels of whatever hides it.
        const auto concealed = [&frame](std::string_view key, std::size_t i) {
            return frame.flagsOf(key, i).concealed;
        };
        const auto& obstacles = truth.list<Obstacle>();
        for (std::size_t i = 0; i < obstacles.size(); ++i) {
            const Obstacle& o = obstacles[i];
            add(rules.obstacle_colour.value_or(Colour::Unclassified),
                box(o.left, o.top, o.right, o.bottom, grow),
                !rules.obstacle_colour || concealed(PerceptTraits<Obstacle>::truth_key, i));
        }
        if (rules.objects_out) {
            for (const FieldLine& l : truth.list<FieldLine>())
                add(Colour::Unclassified, strip(l, rules.line_half_width + shrink), true);
            for (const Goalpost& p : truth.list<Goalpost>())
                add(Colour::Unclassified, box(p.left, p.top, p.right, p.bottom, grow), true);
            for (const Ball& b : truth.list<Ball>())
                add(Colour::Unclassified, disc(b.x, b.y, b.radius + shrink), true);
        }
        for (const FieldLine& l : truth.list<FieldLine>())
            add(Colour::White, strip(l, rules.line_half_width));
        const auto& posts = truth.list<Goalpost>();
        for (std::size_t i = 0; i < posts.size(); ++i)
            add(rules.goal_colour,
                box(posts[i].left, posts[i].top, posts[i].right, posts[i].bottom, -grow),
                concealed(PerceptTraits<Goalpost>::truth_key, i));
        const auto& balls = truth.list<Ball>();
        for (std::size_t i = 0; i < balls.size(); ++i)
            add(Colour::Orange,
                disc(balls[i].x, balls[i].y, std::max(0.5, balls[i].radius - shrink)),
                concealed(PerceptTraits<Ball>::truth_key, i));
    }
    return out;
}

void LutVotes::add(std::uint32_t cell, Colour colour, std::uint32_t votes)
{
    if (cell >= ColourLut::kCells || !isValidColourId(int(colour)))
        return;
    m_votes[cell][std::size_t(colour)] += votes;
    m_pixels += votes;
}

std::size_t LutVotes::addFrame(const cv::Mat& ycbcr, const std::vector<const LutSample*>& samples)
{
    if (ycbcr.empty() || ycbcr.type() != CV_8UC3 || samples.empty())
        return 0;
    cv::Mat labels(ycbcr.size(), CV_8U, cv::Scalar(kNoVote));
    for (const LutSample* s : samples) {
        // Filled with its outline, so a box's corners at inclusive pixels cover the whole box.
        fillPolygon(labels, s->polygon, s->exclude ? kHole : std::uint8_t(s->colour));
    }
    std::size_t voted = 0;
    for (int y = 0; y < ycbcr.rows; ++y) {
        const auto* px = ycbcr.ptr<cv::Vec3b>(y);
        const auto* label = labels.ptr<std::uint8_t>(y);
        for (int x = 0; x < ycbcr.cols; ++x) {
            if (label[x] >= kColourCount)
                continue;
            const auto cell = std::uint32_t(ColourLut::index(px[x][0], px[x][1], px[x][2]));
            ++m_votes[cell][label[x]];
            ++voted;
        }
    }
    m_pixels += voted;
    return voted;
}

ColourLut LutVotes::build(const LutBuildOptions& options) const
{
    ColourLut lut;
    for (const auto& [cell, w] : smoothedWeights(m_votes, options.smoothing)) {
        const Ranking r = rank(w);
        if (r.winner == 0 || r.winner_weight < options.min_weight ||
            r.winner_weight <= r.runner_up_weight)
            continue;
        Colour colour = Colour(r.winner);
        if (options.soft && r.runner_up_weight >= options.ambiguity_ratio * r.winner_weight) {
            if (isPair(r, Colour::Orange, Colour::Pink))
                colour = Colour::PinkOrange;
            else if (isPair(r, Colour::Orange, Colour::Yellow))
                colour = Colour::YellowOrange;
        }
        lut.setCell(cell, colour);
    }
    return lut;
}

std::vector<AmbiguousCell> LutVotes::ambiguousCells(const LutBuildOptions& options) const
{
    std::vector<AmbiguousCell> out;
    for (const auto& [cell, w] : smoothedWeights(m_votes, options.smoothing)) {
        const Ranking r = rank(w);
        if (r.winner_weight < options.min_weight || r.runner_up_weight <= 0 ||
            r.runner_up_weight < options.ambiguity_ratio * r.winner_weight)
            continue;
        out.push_back(
            {cell, Colour(r.winner), Colour(r.runner_up), r.winner_weight, r.runner_up_weight});
    }
    std::sort(out.begin(), out.end(),
              [](const AmbiguousCell& a, const AmbiguousCell& b) { return a.cell < b.cell; });
    return out;
}

Result<LutVoteRun> collectLutVotes(StreamReader& reader, const std::vector<LutSample>& samples,
                                   const LutBuildProgress& progress)
{
    std::map<std::string, std::vector<const LutSample*>> by_stem;
    for (const LutSample& s : samples)
        by_stem[frameStem(s.frame)].push_back(&s);
    std::vector<std::pair<std::size_t, const std::vector<const LutSample*>*>> frames;
    std::map<std::string, bool> found;
    for (std::size_t i = 0; i < reader.info().frame_count; ++i) {
        const auto it = by_stem.find(frameStem(reader.frameName(i)));
        if (it != by_stem.end() && !found[it->first]) {
            found[it->first] = true;
            frames.emplace_back(i, &it->second);
        }
    }
    for (const auto& [stem, list] : by_stem)
        if (!found[stem])
            return Error{reader.info().path + ": no frame \"" + messageText(list.front()->frame) +
                         "\", which a sample names"};

    LutVoteRun run;
    Frame frame;
    for (const auto& [index, list] : frames) {
        if (Status s = reader.readInto(index, frame); !s)
            return s.error();
        run.votes.addFrame(frame.ycbcr, *list);
        ++run.frames;
        if (progress && !progress(run.frames, frames.size())) {
            run.cancelled = run.frames < frames.size();
            break;
        }
    }
    return run;
}

} // namespace fieldsight
