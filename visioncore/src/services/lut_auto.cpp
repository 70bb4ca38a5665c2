// The automatic first table (lut_auto.h): evidence from the frames (lut_auto_evidence.h), one
// Gaussian per class in Y, Cb, Cr, and each cell given to the class its pixels voted for, or
// when none did, to the one class whose Gaussian reaches it; contested cells stay unclassified.
#include "visioncore/services/lut_auto.h"

#include "lut_auto_evidence.h"

#include "visioncore/services/lut_building.h"

#include <Eigen/LU>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>

namespace fieldsight {
namespace {

using autolut::Evidence;
using autolut::EvidenceSet;
using autolut::Gaussian;
using autolut::kEvidenceCount;

/// Frames wider than this are looked at every n-th pixel (nearest, so colours are not blended):
/// the method's sizes are for a 320-wide frame and scale with it.
constexpr int kMaxWidth = 480;
/// Mahalanobis distance (in the stream's carpet) within which a frame's own carpet is taken.
constexpr double kOwnCarpetReach = 8.0;
/// A goal colour whose post pixels are fewer than this share of the other's is not the goal's
/// (a poster, a team's band): the generated streams' true goal colour had 14-16 % of the other's
/// posts at the least (rc2013 seed 315, crowded 401, rc2012 404).
constexpr double kGoalPostsShare = 0.1;
/// Mahalanobis distance (in the ball's colour) within which warm shapes that are not round do not
/// hold a cell back from the ball (fillTable). Crowded seed 316, ball found/false/missed from 40
/// frames: 0/0/43 holding every cell back, 41/6/2 at 1.0, 43/12/0 at 2.0; at 2.0 and 1.5 one false
/// ball on B-Human's red arm returns (40 or 160 frames), at 1.0 none does.
constexpr double kBallCore = 1.0;

cv::Mat workingImage(const cv::Mat& ycbcr)
{
    const int step = (ycbcr.cols + kMaxWidth - 1) / kMaxWidth;
    if (step <= 1)
        return ycbcr.clone();
    cv::Mat small;
    cv::resize(ycbcr, small, cv::Size(ycbcr.cols / step, ycbcr.rows / step), 0, 0,
               cv::INTER_NEAREST);
    return small;
}

/// The first row of the carpet search: below the kinematic horizon, and at least the lower half.
int carpetTop(const Frame& frame, int rows, double shrink)
{
    int top = rows / 2;
    if (frame.horizon) {
        const double lowest = std::max(frame.horizon->y_left, frame.horizon->y_right) / shrink;
        if (std::isfinite(lowest))
            top = std::clamp(int(lowest), top, rows - rows / 8);
    }
    return top;
}

/// The share of a frame's lower part that `carpet` takes.
double carpetShare(const cv::Mat& image, int top, const Gaussian& carpet)
{
    std::size_t all = 0;
    std::size_t taken = 0;
    autolut::forLowerPixels({image}, {top}, [&](const std::uint8_t* px) {
        ++all;
        taken += carpet.distance2(px[0], px[1], px[2]) <= 9.0;
    });
    return all ? double(taken) / double(all) : 0;
}

struct ClassModel
{
    Evidence evidence = Evidence::Green;
    Gaussian gaussian;
    double limit = 3.0; ///< Mahalanobis distance the class reaches
    int lo[3] = {0, 0, 0};
    int hi[3] = {127, 127, 127}; ///< cells, the box around limit
    /// A saturated class reaches only cells at least half as saturated as its mean (squared).
    double min_chroma2 = 0;
};

ClassModel modelOf(const EvidenceSet& evidence, Evidence e, const Eigen::Vector3d& floor,
                   double limit)
{
    ClassModel m;
    m.evidence = e;
    m.limit = limit;
    m.gaussian = evidence.moments[std::size_t(e)].gaussian(floor);
    if (e != Evidence::Green && e != Evidence::White) {
        const double cb = m.gaussian.mean[1] - 128;
        const double cr = m.gaussian.mean[2] - 128;
        m.min_chroma2 = 0.25 * (cb * cb + cr * cr);
    }
    for (int c = 0; c < 3; ++c) {
        const double reach = limit * std::sqrt(m.gaussian.covariance(c, c));
        m.lo[c] = std::clamp(int((m.gaussian.mean[c] - reach) / 2), 0, 127);
        m.hi[c] = std::clamp(int((m.gaussian.mean[c] + reach) / 2), 0, 127);
    }
    return m;
}

/// Each cell: the class most of its pixels voted for, unless another class or the background
/// has half as many; a cell without votes goes to the one class whose Gaussian reaches it
/// clearly nearer than any other's.
ColourLut fillTable(const EvidenceSet& evidence, const std::vector<ClassModel>& models)
{
    ColourLut lut;
    std::array<bool, kEvidenceCount> modelled{};
    const ClassModel* ball = nullptr;
    for (const ClassModel& m : models) {
        modelled[std::size_t(m.evidence)] = true;
        if (m.evidence == Evidence::Orange)
            ball = &m;
    }
    // A warm shape that is not round holds a cell back, except in the core of the colour the
    // round blobs gave the ball: there it is most likely a ball cut by the frame or half hidden
    // by a robot (a crowded field's balls are mostly such).
    const auto held_back = [ball](const auto& n, int y, int cb, int cr) {
        std::uint32_t background = n[std::size_t(Evidence::Background)];
        const std::uint32_t warm = n[std::size_t(Evidence::WarmShape)];
        if (warm && !(ball && ball->gaussian.distance2(2 * y + 1, 2 * cb + 1, 2 * cr + 1) <=
                                  kBallCore * kBallCore))
            background += warm;
        return background;
    };
    for (int y = 0; y < 128; ++y) {
        for (int cb = 0; cb < 128; ++cb) {
            for (int cr = 0; cr < 128; ++cr) {
                const std::uint32_t cell = std::uint32_t((y << 14) | (cb << 7) | cr);
                const auto votes = evidence.cells.find(cell);
                if (votes != evidence.cells.end()) {
                    const auto& n = votes->second;
                    std::size_t best = kEvidenceCount;
                    std::uint32_t first = 0;
                    std::uint32_t second = 0;
                    for (std::size_t e = 0; e < kEvidenceCount; ++e) {
                        if (!modelled[e])
                            continue;
                        if (n[e] > first) {
                            second = first;
                            first = n[e];
                            best = e;
                        } else if (n[e] > second) {
                            second = n[e];
                        }
                    }
                    const std::uint32_t background = held_back(n, y, cb, cr);
                    if (first >= 2) {
                        if (2 * second < first && 2 * background < first)
                            lut.setCell(cell, autolut::evidenceColour(Evidence(best)));
                        continue;
                    }
                    if (background >= 2)
                        continue;
                }
                const double chroma2 = (2 * cb + 1 - 128.0) * (2 * cb + 1 - 128.0) +
                                       (2 * cr + 1 - 128.0) * (2 * cr + 1 - 128.0);
                double nearest = 1e30;
                double runner_up = 1e30;
                const ClassModel* winner = nullptr;
                for (const ClassModel& m : models) {
                    if (y < m.lo[0] || y > m.hi[0] || cb < m.lo[1] || cb > m.hi[1] ||
                        cr < m.lo[2] || cr > m.hi[2])
                        continue;
                    if (m.min_chroma2 > 0 && chroma2 < m.min_chroma2)
                        continue; // too grey for a saturated class
                    const double d2 = m.gaussian.distance2(2 * y + 1, 2 * cb + 1, 2 * cr + 1);
                    if (d2 > m.limit * m.limit)
                        continue;
                    if (d2 < nearest) {
                        runner_up = nearest;
                        nearest = d2;
                        winner = &m;
                    } else if (d2 < runner_up) {
                        runner_up = d2;
                    }
                }
                // Contested: another class's Gaussian reaches the cell almost as near.
                if (winner && runner_up > 1.5 * 1.5 * nearest)
                    lut.setCell(cell, autolut::evidenceColour(winner->evidence));
            }
        }
    }
    return lut;
}

/// Whether a class has pixels enough for a model.
bool enough(const EvidenceSet& evidence, Evidence e)
{
    return evidence.moments[std::size_t(e)].n >= 30;
}

/// The goal colour seen, when any posts were: of the colours whose post pixels are at least
/// kGoalPostsShare of the other's, the one whose posts take the larger share of its shapes near the
/// field. A goal's colour is mostly posts; a colour that also dresses people, robots and walls
/// gives more post pixels (legs and bands standing at the field's edge) but a far smaller share of
/// them: weighing pixels by share (posts^2 / shapes) took blue on 3 of 19 generated streams whose
/// goal is yellow (its share 3-9 %, yellow's 14-21 %); the share alone takes every one of them and
/// B-Human's blue goal (59 % against 0.04 %).
std::optional<Evidence> goalEvidence(const EvidenceSet& evidence)
{
    const EvidenceSet::GoalCue& yellow = evidence.goal(Evidence::Yellow);
    const EvidenceSet::GoalCue& blue = evidence.goal(Evidence::Blue);
    if (yellow.weight() <= 0 && blue.weight() <= 0)
        return std::nullopt;
    // A colour competes when it has pixels enough for a model of its own (the one chosen must
    // be in the table) and posts enough beside the other's.
    const double most = std::max(yellow.posts, blue.posts);
    const auto competes = [&](Evidence e) {
        const EvidenceSet::GoalCue& cue = evidence.goal(e);
        return cue.weight() > 0 && cue.posts >= kGoalPostsShare * most && enough(evidence, e);
    };
    const bool y = competes(Evidence::Yellow);
    const bool b = competes(Evidence::Blue);
    if (y != b)
        return y ? Evidence::Yellow : Evidence::Blue;
    if (!y) // neither has a model: the heavier, as a note names it
        return blue.weight() > yellow.weight() ? Evidence::Blue : Evidence::Yellow;
    return blue.share() > yellow.share() ? Evidence::Blue : Evidence::Yellow;
}

/// The classes with evidence enough, and a note for each expected one left out.
std::vector<ClassModel> classModels(const EvidenceSet& evidence, std::vector<std::string>& notes)
{
    std::vector<ClassModel> models;
    models.push_back(modelOf(evidence, Evidence::Green, {9, 4, 4}, 3.0));
    if (enough(evidence, Evidence::White))
        models.push_back(modelOf(evidence, Evidence::White, {36, 9, 9}, 3.0));
    else
        notes.push_back("no field lines found: no white");
    if (enough(evidence, Evidence::Orange) && evidence.ball_blobs > 0)
        models.push_back(modelOf(evidence, Evidence::Orange, {25, 9, 9}, 3.0));
    else
        notes.push_back("no round ball-coloured blob on the carpet: no orange");
    const std::optional<Evidence> goal = goalEvidence(evidence);
    for (const Evidence e : {Evidence::Yellow, Evidence::Blue}) {
        // A goal colour that weighs far less than the other is noise (a team band, a poster,
        // a wall's or the crowd's colour).
        const auto& cue = evidence.goal(e);
        if (goal && enough(evidence, e) && cue.posts > 0 &&
            5 * cue.weight() >= evidence.goal(*goal).weight())
            models.push_back(modelOf(evidence, e, {25, 9, 9}, 3.0));
    }
    for (const Evidence e : {Evidence::Yellow, Evidence::Blue}) {
        const auto& cue = evidence.goal(e);
        if (cue.shapes > 0)
            notes.push_back(std::string(colourName(autolut::evidenceColour(e))) + ": " +
                            std::to_string(std::lround(cue.posts)) + " px in posts of " +
                            std::to_string(std::lround(cue.shapes)) +
                            " px in shapes near the field");
    }
    if (!goal)
        notes.push_back("no goal-coloured bar standing at the field's edge: no goal colour");
    return models;
}

/// Evidence of classes left out must not hold cells back from the others.
void forgetUnmodelled(EvidenceSet& evidence, const std::vector<ClassModel>& models)
{
    std::array<bool, kEvidenceCount> kept{};
    kept[std::size_t(Evidence::Background)] = true;
    kept[std::size_t(Evidence::WarmShape)] = true;
    for (const ClassModel& m : models)
        kept[std::size_t(m.evidence)] = true;
    for (auto& [cell, counts] : evidence.cells)
        for (std::size_t e = 0; e < kEvidenceCount; ++e)
            if (!kept[e])
                counts[e] = 0;
}

std::optional<Evidence> evidenceOf(Colour colour)
{
    switch (colour) {
    case Colour::Green:
        return Evidence::Green;
    case Colour::White:
        return Evidence::White;
    case Colour::Orange:
        return Evidence::Orange;
    case Colour::Yellow:
        return Evidence::Yellow;
    case Colour::Blue:
        return Evidence::Blue;
    case Colour::Unclassified:
        return Evidence::Background;
    default:
        return std::nullopt;
    }
}

/// The annotated regions of the done frames vote as `lut build` takes them (the goal in
/// `goal_colour`). Returns a note of what they added.
Result<std::string> addAnnotations(StreamReader& reader, const Annotations& annotations,
                                   Colour goal_colour, EvidenceSet& evidence)
{
    AnnotationSampleRules rules;
    rules.goal_colour = goal_colour;
    const StreamInfo& info = reader.info();
    const std::vector<LutSample> samples =
        samplesFromAnnotations(annotations, {info.width, info.height}, rules);
    auto voted = collectLutVotes(reader, samples);
    if (!voted)
        return voted.error();
    std::size_t added = 0;
    for (const auto& [cell, counts] : voted.value().votes.cells()) {
        for (int c = 0; c < kColourCount; ++c) {
            const std::optional<Evidence> e = evidenceOf(Colour(c));
            if (!e || counts[std::size_t(c)] == 0)
                continue;
            evidence.addCell(*e, cell, counts[std::size_t(c)]);
            added += counts[std::size_t(c)];
            if (*e == Evidence::Orange)
                evidence.ball_blobs += 1;
            else if (*e == Evidence::Yellow || *e == Evidence::Blue) {
                evidence.goal(*e).posts += counts[std::size_t(c)];
                evidence.goal(*e).shapes += counts[std::size_t(c)];
            }
        }
    }
    return "the annotations of " + std::to_string(voted.value().frames) + " frames voted " +
           std::to_string(added) + " pixels";
}

} // namespace

Result<AutoLut> buildAutoLut(StreamReader& reader, const AutoLutOptions& options,
                             const AutoLutProgress& progress)
{
    AutoLut out;
    const std::size_t total = reader.info().frame_count;
    const std::size_t n = options.frames == 0 ? total : std::min(total, options.frames);
    if (n == 0)
        return Error{reader.info().path + ": no frames to make a table from"};

    // Frames spread evenly over the stream, each index once.
    std::vector<cv::Mat> frames;
    std::vector<int> tops;
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t index = n == total ? i : (i * total + total / (2 * n)) / n;
        auto frame = reader.read(std::min(index, total - 1));
        if (!frame)
            return frame.error();
        cv::Mat image = workingImage(frame.value().ycbcr);
        const double shrink = double(frame.value().ycbcr.cols) / image.cols;
        tops.push_back(carpetTop(frame.value(), image.rows, shrink));
        frames.push_back(std::move(image));
        ++out.frames;
        if (progress && !progress(i + 1, n)) {
            out.cancelled = true;
            break;
        }
    }

    const std::optional<Gaussian> carpet = autolut::findCarpet(frames, tops);
    if (!carpet) {
        out.notes.push_back(
            "no carpet found: no chroma cluster fills the lower part of the frames");
        return out;
    }
    EvidenceSet evidence;
    // A frame the camera exposed differently shows its carpet elsewhere: its own dominant
    // cluster, when near the stream's, finds its carpet.
    for (std::size_t f = 0; f < frames.size(); ++f) {
        std::optional<Gaussian> own;
        if (carpetShare(frames[f], tops[f], *carpet) < 0.3)
            own = autolut::findCarpet({frames[f]}, {tops[f]});
        const bool near = own && carpet->distance2(own->mean[0], own->mean[1], own->mean[2]) <=
                                     kOwnCarpetReach * kOwnCarpetReach;
        autolut::collectEvidence(frames[f], near ? *own : *carpet, evidence);
    }

    if (const auto goal = goalEvidence(evidence))
        out.goal_colour = autolut::evidenceColour(*goal);
    if (options.annotations && !out.cancelled) {
        auto added = addAnnotations(reader, *options.annotations,
                                    out.goal_colour.value_or(Colour::Yellow), evidence);
        if (!added)
            return added.error();
        out.notes.push_back(added.value());
    }
    const std::vector<ClassModel> models = classModels(evidence, out.notes);
    forgetUnmodelled(evidence, models);
    out.lut = fillTable(evidence, models);

    // What the table gives the sampled pixels.
    std::array<std::size_t, kColourCount> pixels{};
    std::size_t sampled = 0;
    cv::Mat classes;
    for (const cv::Mat& image : frames) {
        out.lut.classifyImage(image, classes);
        for (int y = 0; y < classes.rows; ++y) {
            const std::uint8_t* row = classes.ptr<std::uint8_t>(y);
            for (int x = 0; x < classes.cols; ++x)
                ++pixels[row[x]];
        }
        sampled += std::size_t(classes.total());
    }
    std::array<std::size_t, kColourCount> cells{};
    for (std::size_t i = 0; i < ColourLut::kCells; ++i)
        ++cells[out.lut.data()[i]];
    for (int c = 1; c < kColourCount; ++c) {
        if (cells[std::size_t(c)] == 0)
            continue;
        out.classes.push_back({Colour(c), cells[std::size_t(c)],
                               sampled ? double(pixels[std::size_t(c)]) / double(sampled) : 0});
    }
    return out;
}

std::optional<GoalColourParam> goalColourParam(const Pipeline& pipeline)
{
    for (const StageDescriptor& stage : pipeline.descriptors())
        for (const ParamInfo& param : stage.params)
            if (param.name == "goal_colour" && param.kind == ParamKind::Choice)
                return GoalColourParam{stage.info.id, param.name, param.default_value};
    return std::nullopt;
}

} // namespace fieldsight
