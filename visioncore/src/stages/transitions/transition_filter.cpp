// Replacement rules, segment joining and transition matching.
#include "stages/transitions/transition_filter.h"

#include "stages/common/stage_util.h"
#include "visioncore/framework/blackboard.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fieldsight {

namespace {

using Rule = ReplacementRule;
constexpr Colour kGreen = Colour::Green;
constexpr Colour kUncl = Colour::Unclassified;

/// One rule in one orientation, for one (before, middle, after) colour triple: only the length
/// bounds are left to check. Unbounded maxima are INT_MAX.
struct OrientedRule
{
    int min_b, max_b, min_m, max_m, min_a, max_a;
    Colour result;      ///< the middle's new colour (Before/After)
    bool split = false; ///< Split: halves take the colours of their own neighbours
};

/// The oriented rules that can apply to a colour triple, in the order the rules are tried (rule by
/// rule, forward before backward; the first whose lengths fit wins). `uniform`: every one of them
/// gives `result`, so whether any fits is all that matters and no early exit is needed.
struct TripleRules
{
    std::uint16_t begin = 0, end = 0;
    bool uniform = true;
    Colour result = Colour::Unclassified;
};

constexpr std::size_t tripleIndex(Colour b, Colour m, Colour a)
{
    return (std::size_t(b) * kColourCount + std::size_t(m)) * kColourCount + std::size_t(a);
}

struct RuleTable
{
    std::vector<OrientedRule> rules;
    std::array<TripleRules, std::size_t(kColourCount) * kColourCount * kColourCount> triples{};
    bool any_split = false;
};

bool colourFits(const Rule::Part& part, Colour c)
{
    return part.colours.empty() ||
           std::find(part.colours.begin(), part.colours.end(), c) != part.colours.end();
}

int upper(int max)
{
    return max < 0 ? std::numeric_limits<int>::max() : max;
}

/// The default rules compiled per colour triple, so the hot loop does one table lookup per segment
/// and a few branch-free length comparisons (noise makes every data-dependent branch a coin toss).
const RuleTable& ruleTable()
{
    static const RuleTable table = [] {
        RuleTable t;
        for (int bi = 0; bi < kColourCount; ++bi)
            for (int mi = 0; mi < kColourCount; ++mi)
                for (int ai = 0; ai < kColourCount; ++ai) {
                    const Colour b = Colour(bi), m = Colour(mi), a = Colour(ai);
                    TripleRules& entry = t.triples[tripleIndex(b, m, a)];
                    entry.begin = std::uint16_t(t.rules.size());
                    for (const Rule& r : defaultReplacementRules()) {
                        if (r.middle.colours.empty() || !colourFits(r.middle, m))
                            continue;
                        for (const bool forward : {true, false}) {
                            const Colour nb = forward ? b : a, na = forward ? a : b;
                            if (!colourFits(r.before, nb) || !colourFits(r.after, na))
                                continue;
                            // Lengths stay in scan order: backward, "before" is the next segment.
                            const Rule::Part& first = forward ? r.before : r.after;
                            const Rule::Part& last = forward ? r.after : r.before;
                            OrientedRule o{first.min,
                                           upper(first.max),
                                           r.middle.min,
                                           upper(r.middle.max),
                                           last.min,
                                           upper(last.max),
                                           r.method == Rule::Method::Before ? nb : na,
                                           r.method == Rule::Method::Split};
                            t.any_split = t.any_split || o.split;
                            if (entry.end == entry.begin) // first one: sets the result
                                entry.result = o.result;
                            entry.uniform = entry.uniform && !o.split && o.result == entry.result;
                            t.rules.push_back(o);
                            entry.end = std::uint16_t(t.rules.size());
                        }
                    }
                }
        return t;
    }();
    return table;
}

[[gnu::always_inline]] inline bool lengthsFit(const OrientedRule& r, int lb, int lm, int la)
{
    // & rather than &&: no branches.
    return (lb >= r.min_b) & (lb <= r.max_b) & (lm >= r.min_m) & (lm <= r.max_m) & (la >= r.min_a) &
           (la <= r.max_a);
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

const StageInfo& TransitionFilter::info() const
{
    static const StageInfo info{
        "transitions",
        "Transition filter",
        "Replacement rules clean noise out of the segments; segments of the object colours become "
        "that object's transitions.",
        false,
        {"segments"},
        {"filtered_segments", "transitions"},
        {},
        {{"transitions.filtered_segments", "Filtered segments", {}, true},
         {"transitions.transitions", "Transitions", debug_colour::kCyan}}};
    return info;
}

void TransitionFilter::filterRegion(const SegmentedRegion& in, SegmentedRegion& out) const
{
    const RuleTable& table = ruleTable();
    for (std::size_t i = 0; i < in.size(); ++i) {
        const Scan& scan = in[i];
        Scan& filtered = out.addScan();
        const std::size_t n = scan.size();
        if (n == 0)
            continue;
        // Written by index and trimmed at the end. The output never has more segments than the
        // input unless a rule splits, so a copy of the input is storage enough (and cheaper than
        // resize(), which would construct every element first).
        if (table.any_split)
            filtered.resize(2 * n);
        else
            filtered.assign(scan.begin(), scan.end());
        ColourSegment* o = filtered.data();
        std::size_t m = 0;
        // The segment being built, joined with every following one of its colour. Branch-free:
        // it is stored at o[m] every time, and m only moves on when the colour changes.
        ColourSegment cur = scan[0];
        const auto append = [&](const ColourSegment& seg) {
            const bool changes = cur.colour != seg.colour;
            o[m] = cur;
            m += std::size_t(changes);
            cur.x0 = changes ? seg.x0 : cur.x0;
            cur.y0 = changes ? seg.y0 : cur.y0;
            cur.x1 = seg.x1;
            cur.y1 = seg.y1;
            cur.colour = seg.colour;
        };
        int lb = scan[0].length();
        int lm = n > 1 ? scan[1].length() : 0;
        // Rules look at the original neighbours, so replacements never cascade; the first and
        // last segments have one neighbour and are never replaced.
        for (std::size_t k = 1; k + 1 < n; ++k) {
            const ColourSegment& b = scan[k - 1];
            ColourSegment seg = scan[k];
            const ColourSegment& a = scan[k + 1];
            const int la = a.length();
            const TripleRules& t = table.triples[tripleIndex(b.colour, seg.colour, a.colour)];
            if (t.uniform) {
                bool fits = false;
                for (std::size_t r = t.begin; r < t.end; ++r)
                    fits |= lengthsFit(table.rules[r], lb, lm, la);
                seg.colour = fits ? t.result : seg.colour;
            } else {
                for (std::size_t r = t.begin; r < t.end; ++r) {
                    const OrientedRule& rule = table.rules[r];
                    if (!lengthsFit(rule, lb, lm, la))
                        continue;
                    if (rule.split) {
                        // Split at the midpoint: each half takes its own neighbour's colour.
                        ColourSegment first = seg, second = seg;
                        const int mx = (seg.x0 + seg.x1) / 2, my = (seg.y0 + seg.y1) / 2;
                        first.x1 = second.x0 = std::int16_t(mx);
                        first.y1 = second.y0 = std::int16_t(my);
                        first.colour = b.colour;
                        second.colour = a.colour;
                        if (first.length() > 0)
                            append(first);
                        seg = second;
                    } else {
                        seg.colour = rule.result;
                    }
                    break;
                }
            }
            if (seg.length() > 0)
                append(seg);
            lb = lm;
            lm = la;
        }
        if (n > 1)
            append(scan[n - 1]);
        o[m++] = cur;
        filtered.resize(m);
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
    const auto add = [&](Colour colour, TransitionClass cls, int min, int max) {
        Rules& r = by_colour[std::size_t(colour)];
        r.rules[std::size_t(r.count++)] = {cls, min, max};
    };
    constexpr int kUnbounded = 1000000;
    add(m_ball_colour, TransitionClass::Ball, m_min_ball_length, kUnbounded);
    add(m_goal_colour, TransitionClass::Goal, m_min_goal_length, kUnbounded);
    add(Colour::White, TransitionClass::Line, m_min_line_length, kUnbounded);
    add(Colour::Blue, TransitionClass::TeamCyan, m_min_team_length, m_max_team_length);
    add(Colour::Pink, TransitionClass::TeamMagenta, m_min_team_length, m_max_team_length);

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
