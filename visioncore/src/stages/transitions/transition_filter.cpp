// Replacement rules, segment joining and transition matching.
#include "stages/transitions/transition_filter.h"

#include "stages/common/stage_util.h"
#include "visioncore/blackboard.h"

#include <algorithm>
#include <cmath>

namespace fieldsight {

namespace {

using Rule = ReplacementRule;
constexpr Colour kGreen = Colour::Green;
constexpr Colour kUncl = Colour::Unclassified;

/// A rule part compiled for the hot loop: colour lists become bit sets.
struct CompiledPart
{
    int min = 0;
    int max = -1;      ///< < 0: unbounded
    unsigned mask = 0; ///< 0: any colour
};

struct CompiledRule
{
    CompiledPart before, middle, after;
    Rule::Method method;
};

CompiledPart compile(const Rule::Part& part)
{
    CompiledPart c{part.min, part.max, 0};
    for (Colour colour : part.colours)
        c.mask |= 1u << unsigned(colour);
    return c;
}

[[gnu::always_inline]] inline bool partMatches(const CompiledPart& part, const ColourSegment& s)
{
    const int len = s.length();
    return len >= part.min && (part.max < 0 || len <= part.max) &&
           (part.mask == 0 || (part.mask >> unsigned(s.colour) & 1u));
}

/// The compiled default rules of one middle colour, and the colours any of them accepts next to
/// it (a segment whose neighbours are not both among those skips the rules).
struct RulesForColour
{
    std::vector<CompiledRule> rules;
    unsigned neighbours = 0;
};

const std::array<RulesForColour, kColourCount>& rulesByMiddleColour()
{
    static const auto table = [] {
        std::array<RulesForColour, kColourCount> t;
        for (const Rule& r : defaultReplacementRules())
            for (Colour c : r.middle.colours) {
                RulesForColour& entry = t[std::size_t(c)];
                entry.rules.push_back(
                    {compile(r.before), compile(r.middle), compile(r.after), r.method});
                for (const CompiledPart& part :
                     {entry.rules.back().before, entry.rules.back().after})
                    entry.neighbours |= part.mask == 0 ? ~0u : part.mask;
            }
        return t;
    }();
    return table;
}

} // namespace

const std::vector<ReplacementRule>& defaultReplacementRules()
{
    using M = Rule::Method;
    static const std::vector<Rule> rules{
        {"fieldnoise_v_small", {3, -1, {kGreen}}, {0, 1, {kUncl}}, {3, -1, {kGreen}}, M::Before},
        {"fieldnoise_v_med", {6, -1, {kGreen}}, {0, 2, {kUncl}}, {6, -1, {kGreen}}, M::Before},
        {"fieldnoise_v_large", {12, -1, {kGreen}}, {0, 4, {kUncl}}, {12, -1, {kGreen}}, M::Before},
        {"fieldnoise_v_oneway", {1, -1, {kGreen}}, {0, 4, {kUncl}}, {12, -1, {kGreen}}, M::Before},
        {"fieldnoise_v_oneway2",
         {3, -1, {kGreen}},
         {0, 10, {kUncl}},
         {20, -1, {kGreen}},
         M::Before},
        {"yellowgoal1",
         {1, -1, {Colour::Yellow}},
         {0, 1, {Colour::Orange}},
         {5, -1, {Colour::Yellow}},
         M::After},
        {"yellowgoal2",
         {5, -1, {Colour::Yellow}},
         {0, 3, {kUncl}},
         {1, -1, {Colour::Yellow}},
         M::After},
        // Not in the original: sensor noise splits a distant post (a few px wide) into pieces too
        // short to be transitions. Blue for the 2009 goals.
        {"goalnoise_yellow",
         {1, -1, {Colour::Yellow}},
         {0, 1, {kUncl}},
         {1, -1, {Colour::Yellow}},
         M::Before},
        {"goalnoise_blue",
         {1, -1, {Colour::Blue}},
         {0, 1, {kUncl}},
         {1, -1, {Colour::Blue}},
         M::Before},
        {"ball1", {5, -1, {Colour::Orange}}, {0, 3, {kUncl}}, {1, -1, {Colour::Orange}}, M::Before},
        {"line1", {1, -1, {Colour::White}}, {0, 3, {kUncl}}, {5, -1, {Colour::White}}, M::Before},
    };
    return rules;
}

TransitionFilter::TransitionFilter()
{
    addParam(m_goal_colour, {"goal_colour", "class id",
                             "colour class of the goalposts (8 yellow; 9 blue for B-Human logs)",
                             double(Colour::Yellow), 0, kColourCount - 1});
    addParam(m_ball_colour, {"ball_colour", "class id", "colour class of the ball",
                             double(Colour::Orange), 0, kColourCount - 1});
    addParam(m_min_ball_length, {"min_ball_length", "px", "shortest ball segment", 3, 1, 100});
    addParam(m_min_goal_length,
             {"min_goal_length", "px",
              "shortest goal segment (3 in the original; a far post is 2 px wide)", 2, 1, 100});
    addParam(m_min_line_length, {"min_line_length", "px", "shortest line segment", 2, 1, 100});
    addParam(m_min_team_length,
             {"min_team_length", "px", "shortest team marker segment", 2, 1, 100});
    addParam(m_max_team_length,
             {"max_team_length", "px", "longest team marker segment", 50, 1, 1000});
}

const StageInfo& TransitionFilter::info() const
{
    static const StageInfo info{"transitions",
                                "Transition filter",
                                false,
                                {"horizontal_segments", "vertical_segments"},
                                {"horizontal_filtered", "vertical_filtered",
                                 "horizontal_transitions", "vertical_transitions"},
                                {{"transitions.filtered_segments", "Filtered segments"},
                                 {"transitions.transitions", "Transitions"}}};
    return info;
}

void TransitionFilter::filterRegion(const SegmentedRegion& in, SegmentedRegion& out) const
{
    const auto& by_middle = rulesByMiddleColour();
    static const std::vector<CompiledRule> kNoRules;
    for (std::size_t i = 0; i < in.size(); ++i) {
        const Scan& scan = in[i];
        Scan& filtered = out.addScan();
        const std::size_t n = scan.size();
        for (std::size_t k = 0; k < n; ++k) {
            ColourSegment seg = scan[k];
            // Rules look at the original neighbours, so replacements never cascade. Most segments
            // (green, white) are no rule's middle and skip this.
            if (k > 0 && k + 1 < n) {
                const ColourSegment& b = scan[k - 1];
                const ColourSegment& a = scan[k + 1];
                const RulesForColour& candidates = by_middle[std::size_t(seg.colour)];
                const bool possible = (candidates.neighbours >> unsigned(b.colour) & 1u) &&
                                      (candidates.neighbours >> unsigned(a.colour) & 1u);
                for (const CompiledRule& r : possible ? candidates.rules : kNoRules) {
                    if (!partMatches(r.middle, seg))
                        continue;
                    const bool forward = partMatches(r.before, b) && partMatches(r.after, a);
                    if (!forward && !(partMatches(r.before, a) && partMatches(r.after, b)))
                        continue;
                    const ColourSegment& before = forward ? b : a;
                    const ColourSegment& after = forward ? a : b;
                    if (r.method == Rule::Method::Before) {
                        seg.colour = before.colour;
                    } else if (r.method == Rule::Method::After) {
                        seg.colour = after.colour;
                    } else {
                        // Split at the midpoint: each half takes its own neighbour's colour.
                        ColourSegment first = seg, second = seg;
                        const int mx = (seg.x0 + seg.x1) / 2, my = (seg.y0 + seg.y1) / 2;
                        first.x1 = second.x0 = std::int16_t(mx);
                        first.y1 = second.y0 = std::int16_t(my);
                        first.colour = b.colour;
                        second.colour = a.colour;
                        if (first.length() > 0)
                            filtered.push_back(first);
                        seg = second;
                    }
                    break;
                }
            }
            // Join with the previous segment when the colours now agree.
            if (!filtered.empty() && filtered.back().colour == seg.colour) {
                filtered.back().x1 = seg.x1;
                filtered.back().y1 = seg.y1;
            } else if (seg.length() > 0) {
                filtered.push_back(seg);
            }
        }
    }
}

void TransitionFilter::matchTransitions(const SegmentedRegion& region, Transitions& out) const
{
    // The original's transition rules all have "any" neighbours, so a transition is a segment of
    // the class colour within the length bounds. Its team rules named "cyan"/"magenta", which are
    // not colours, so they never matched; here they are blue and pink.
    struct ClassRule
    {
        TransitionClass cls;
        int min, max;
    };
    struct Rules
    {
        std::array<ClassRule, kTransitionClassCount> rules;
        int count = 0;
    };
    std::array<Rules, kColourCount> by_colour{};
    const auto add = [&](double colour, TransitionClass cls, double min, double max) {
        const int c = int(std::lround(colour));
        if (isValidColourId(c)) {
            Rules& r = by_colour[std::size_t(c)];
            r.rules[std::size_t(r.count++)] = {cls, int(std::lround(min)), int(std::lround(max))};
        }
    };
    add(m_ball_colour, TransitionClass::Ball, m_min_ball_length, 1e6);
    add(m_goal_colour, TransitionClass::Goal, m_min_goal_length, 1e6);
    add(double(Colour::White), TransitionClass::Line, m_min_line_length, 1e6);
    add(double(Colour::Blue), TransitionClass::TeamCyan, m_min_team_length, m_max_team_length);
    add(double(Colour::Pink), TransitionClass::TeamMagenta, m_min_team_length, m_max_team_length);

    for (std::size_t i = 0; i < region.size(); ++i)
        for (const ColourSegment& s :
             region[i]) // single-segment scans count too (unlike the original)
        {
            const Rules& rules = by_colour[std::size_t(s.colour)];
            for (int k = 0; k < rules.count; ++k) {
                const ClassRule& r = rules.rules[std::size_t(k)];
                const int len = s.length();
                if (len >= r.min && len <= r.max)
                    out[r.cls].push_back(s);
            }
        }
}

void TransitionFilter::run(Blackboard& bb)
{
    filterRegion(bb.horizontal_segments, bb.horizontal_filtered);
    filterRegion(bb.vertical_segments, bb.vertical_filtered);
    matchTransitions(bb.horizontal_filtered, bb.horizontal_transitions);
    matchTransitions(bb.vertical_filtered, bb.vertical_transitions);

    if (auto* d = bb.debug.layer("transitions.filtered_segments"))
        for (const SegmentedRegion* region : {&bb.horizontal_filtered, &bb.vertical_filtered})
            for (std::size_t i = 0; i < region->size(); ++i)
                for (const ColourSegment& s : (*region)[i]) {
                    const PixelPoint last = s.last();
                    d->add(lineShape({double(s.x0), double(s.y0)}, {double(last.x), double(last.y)},
                                     colourDisplayRgb(s.colour)));
                }
    if (auto* d = bb.debug.layer("transitions.transitions")) {
        DebugShape dots{ShapeKind::Points, {}, debug_colour::kCyan, 2, false};
        for (const Transitions* t : {&bb.horizontal_transitions, &bb.vertical_transitions})
            for (int c = 0; c < kTransitionClassCount; ++c)
                for (const ColourSegment& s : t->of[std::size_t(c)]) {
                    if (TransitionClass(c) == TransitionClass::Line) {
                        dots.points.push_back(s.centre());
                    } else {
                        const PixelPoint last = s.last();
                        dots.points.push_back({double(s.x0), double(s.y0)});
                        dots.points.push_back({double(last.x), double(last.y)});
                    }
                }
        d->add(std::move(dots));
    }
}

} // namespace fieldsight
