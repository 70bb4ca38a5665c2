// One frame's percepts, of any kind: what the stages write, results JSON, annotations (ground
// truth) and evaluation all use this one type, with one JSON reader/writer and one drawing.
#pragma once

#include "visioncore/basics/colour.h"
#include "visioncore/basics/debug_drawing.h"

#include <nlohmann/json_fwd.hpp>

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fieldsight {

/// Which JSON names a set is read or written with.
enum class PerceptNames {
    Results, ///< PerceptKind::key (fieldsight-results/1)
    Truth,   ///< PerceptKind::truth_key (fieldsight-annotations/1)
};

/// Describes percept type P to the framework. Specialise it next to P (see percepts/ball.h) with:
///
///     static constexpr std::string_view key = "balls";   // its list in results JSON
///     static constexpr std::string_view truth_key = key; // its list in annotations (SPEC §5.2)
///     static constexpr std::string_view title = "Balls"; // for layer lists
///     static constexpr Rgb colour{255, 160, 0};          // its colour in every drawing
///     static void toJson(const std::vector<P>&, PerceptNames names, nlohmann::ordered_json&
///     value);
///     /// A message "<where>... must be ..." on bad input.
///     static std::optional<std::string> fromJson(const nlohmann::json& value, PerceptNames names,
///                                                const std::string& where, std::vector<P>& out);
///
/// (`names` tells results from annotations, where a percept may have fewer fields.)
///     static void draw(const std::vector<P>&, Rgb colour, double width, DebugDrawing& out);
///
/// A new kind of percept is its struct, this specialisation, and a stage that declares it in its
/// StageInfo::percepts; results and annotations JSON and the layers follow.
///
/// A kind `eval` scores by matching detections to true objects (SPEC §5.3) says so in its traits
/// (optional), with its class's name and rule; the scores, the eval command, the evaluation
/// panel and the edit effect follow:
///
///     static constexpr std::string_view class_name = "ball"; // eval's name ("_" a space in text)
///     static constexpr int class_order = 1;                   // scores list classes by it
///     /// The cost of pairing (smaller pairs first), or nothing when they do not match.
///     static std::optional<double> matchCost(const P& detected, const P& truth, int width,
///                                            int height);
template <class P> struct PerceptTraits;

class PerceptEntry;

/// How an annotator draws a kind's objects: the annotation tools follow this, naming no kind.
/// A kind says so in its traits (optional):
///
///     static constexpr ShapeForm form = ShapeForm::Circle;
///     static EditShape shapeOf(const P&);
///     static P fromShape(const EditShape&);
enum class ShapeForm {
    None,     ///< not drawn by hand
    Circle,   ///< points {centre}, radius
    Box,      ///< points {top-left, bottom-right}, inclusive pixels
    Polyline, ///< its points, left to right; at most one a frame
    Segment,  ///< points {one end, the other}
};

/// One object as editable geometry, px (see ShapeForm).
struct EditShape
{
    std::vector<PointF> points;
    double radius = 0;
    friend bool operator==(const EditShape&, const EditShape&) = default;
};

/// A detection and a true object its kind's rule pairs (indices into the two lists), and how
/// near they are: the cost orders the greedy matching, smaller first.
struct MatchCandidate
{
    double cost = 0;
    std::size_t detection = 0;
    std::size_t truth = 0;
};

/// A percept type at run time: its names, its colour, how to make an empty list of it, how it is
/// drawn by hand, and how it is scored.
struct PerceptKind
{
    std::string_view key;
    std::string_view truth_key;
    std::string_view title;
    Rgb colour;
    std::unique_ptr<PerceptEntry> (*make)();
    ShapeForm form = ShapeForm::None;
    /// How eval names its class (PerceptTraits::class_name); empty: not scored by matching.
    std::string_view class_name = {};
    int class_order = 0; ///< scores list the classes by this, then by pipeline order
    /// Every pair of a detection and a true object (lists of this kind in an image of width x
    /// height px; null: an absent list) that its rule accepts, with its cost. Null when the kind
    /// is not scored by matching.
    std::vector<MatchCandidate> (*match)(const PerceptEntry* detected, const PerceptEntry* truth,
                                         int width, int height) = nullptr;
};

template <class P> const PerceptKind& perceptKind();

/// A list of percepts of one kind, type-erased. Absent (not present) means the stage that writes
/// it did not run; present and empty means it ran and found nothing.
class PerceptEntry
{
public:
    explicit PerceptEntry(const PerceptKind& kind) : m_kind(&kind) {}
    virtual ~PerceptEntry() = default;
    const PerceptKind& kind() const { return *m_kind; }
    virtual std::size_t size() const = 0;
    virtual void clear() = 0;
    virtual std::unique_ptr<PerceptEntry> clone() const = 0;
    virtual void toJson(PerceptNames names, nlohmann::ordered_json& value) const = 0;
    virtual std::optional<std::string> fromJson(const nlohmann::json& value, PerceptNames names,
                                                const std::string& where) = 0;
    virtual void draw(Rgb colour, double width, DebugDrawing& out) const = 0;
    /// The objects as editable geometry (none when the kind's form is None).
    virtual std::vector<EditShape> shapes() const = 0;
    /// Replaces the objects by `shapes` (nothing when the kind's form is None).
    virtual void setShapes(const std::vector<EditShape>& shapes) = 0;

    bool present() const { return m_present; }

private:
    friend class PerceptSet; // keeps count of the present entries
    const PerceptKind* m_kind;
    bool m_present = false;
};

template <class P> class PerceptList final : public PerceptEntry
{
public:
    using Traits = PerceptTraits<P>;
    PerceptList() : PerceptEntry(perceptKind<P>()) {}
    std::size_t size() const override { return items.size(); }
    void clear() override { items.clear(); }
    std::unique_ptr<PerceptEntry> clone() const override
    {
        return std::make_unique<PerceptList<P>>(*this);
    }
    void toJson(PerceptNames names, nlohmann::ordered_json& value) const override
    {
        Traits::toJson(items, names, value);
    }
    std::optional<std::string> fromJson(const nlohmann::json& value, PerceptNames names,
                                        const std::string& where) override
    {
        items.clear();
        return Traits::fromJson(value, names, where, items);
    }
    void draw(Rgb colour, double width, DebugDrawing& out) const override
    {
        Traits::draw(items, colour, width, out);
    }
    std::vector<EditShape> shapes() const override
    {
        std::vector<EditShape> out;
        if constexpr (requires { Traits::shapeOf(items.front()); })
            for (const P& item : items)
                out.push_back(Traits::shapeOf(item));
        return out;
    }
    void setShapes(const std::vector<EditShape>& shapes) override
    {
        if constexpr (requires(const EditShape& s) { Traits::fromShape(s); }) {
            items.clear();
            for (const EditShape& shape : shapes)
                items.push_back(Traits::fromShape(shape));
        }
    }

    std::vector<P> items;
};

/// Every pair of `detected` and `truth` that PerceptTraits<P>::matchCost accepts.
template <class P>
std::vector<MatchCandidate> matchCandidates(const std::vector<P>& d, const std::vector<P>& t,
                                            int width, int height)
{
    std::vector<MatchCandidate> out;
    for (std::size_t ti = 0; ti < t.size(); ++ti)
        for (std::size_t di = 0; di < d.size(); ++di)
            if (const std::optional<double> cost =
                    PerceptTraits<P>::matchCost(d[di], t[ti], width, height))
                out.push_back({*cost, di, ti});
    return out;
}

/// PerceptKind::match of a kind whose traits have a matchCost.
template <class P>
std::vector<MatchCandidate> matchEntries(const PerceptEntry* detected, const PerceptEntry* truth,
                                         int width, int height)
{
    static const std::vector<P> none;
    return matchCandidates<P>(detected ? static_cast<const PerceptList<P>*>(detected)->items : none,
                              truth ? static_cast<const PerceptList<P>*>(truth)->items : none,
                              width, height);
}

template <class P> const PerceptKind& perceptKind()
{
    using T = PerceptTraits<P>;
    constexpr bool scored = requires
    {
        &T::matchCost;
    };
    static const PerceptKind kind{
        T::key,
        T::truth_key,
        T::title,
        T::colour,
        []() -> std::unique_ptr<PerceptEntry> { return std::make_unique<PerceptList<P>>(); },
        [] {
            if constexpr (requires { T::form; })
                return T::form;
            else
                return ShapeForm::None;
        }(),
        [] {
            if constexpr (scored)
                return std::string_view(T::class_name);
            else
                return std::string_view();
        }(),
        [] {
            if constexpr (scored)
                return int(T::class_order);
            else
                return 0;
        }(),
        []() -> decltype(PerceptKind::match) {
            if constexpr (scored)
                return &matchEntries<P>;
            else
                return nullptr;
        }()};
    return kind;
}

/// Layer id prefixes of the percept drawings ("percepts.balls", "truth.field_boundary").
inline constexpr std::string_view kPerceptLayerPrefix = "percepts";
inline constexpr std::string_view kTruthLayerPrefix = "truth";
/// Ground truth is drawn white over a black rim, thin, so it shows on carpet, walls and lines alike
/// and never looks like a detection; detections in their kind's colour over a black rim.
inline constexpr Rgb kTruthColour{255, 255, 255};
inline constexpr double kTruthLineWidth = 1;
inline constexpr double kPerceptLineWidth = 2;
inline constexpr Rgb kPerceptRimColour{0, 0, 0};

class PerceptSet
{
public:
    PerceptSet() = default;
    PerceptSet(const PerceptSet& other);
    PerceptSet& operator=(const PerceptSet& other);
    PerceptSet(PerceptSet&&) noexcept = default;
    PerceptSet& operator=(PerceptSet&&) noexcept = default;
    ~PerceptSet();

    /// The list a stage writes: marked present (kept, if already present). Kinds appear in JSON
    /// in the order they were first added.
    template <class P> std::vector<P>& output()
    {
        auto& list = static_cast<PerceptList<P>&>(entry(perceptKind<P>()));
        markPresent(list);
        return list.items;
    }
    /// The list of kind P, or nullptr when absent.
    template <class P> const std::vector<P>* find() const
    {
        const PerceptEntry* e = find(perceptKind<P>());
        return e && e->present() ? &static_cast<const PerceptList<P>*>(e)->items : nullptr;
    }
    /// The list of kind P; empty when absent.
    template <class P> const std::vector<P>& list() const
    {
        static const std::vector<P> none;
        const std::vector<P>* l = find<P>();
        return l ? *l : none;
    }

    /// The entry of `kind`, created (absent) when missing.
    PerceptEntry& entry(const PerceptKind& kind);
    /// Marks `e` (an entry of this set) present.
    void markPresent(PerceptEntry& e)
    {
        m_present_count += !e.m_present;
        e.m_present = true;
    }
    const PerceptEntry* find(const PerceptKind& kind) const;
    /// Present entries, in order.
    std::vector<const PerceptEntry*> entries() const;
    std::size_t presentCount() const { return m_present_count; }
    /// Every entry absent and empty (their memory is kept for the next frame).
    void clear();

    /// Adds every present list to `object` under its key: those of `order` first, in that order
    /// (so a set's JSON does not depend on the order its lists were made in), then the rest.
    void toJson(nlohmann::ordered_json& object, PerceptNames names,
                const std::vector<const PerceptKind*>& order = {}) const;
    /// Reads the lists of `kinds` found in `object` (others are left absent; unknown keys are
    /// ignored). On bad input, returns "<where>.<key>... must be ...".
    std::optional<std::string> fromJson(const nlohmann::json& object,
                                        const std::vector<const PerceptKind*>& kinds,
                                        PerceptNames names, const std::string& where);

    /// One layer "<prefix>.<key>" per present list: detections in their kind's colour, or (with
    /// `truth`) everything thin in kTruthColour, under the prefix "truth" and the truth keys.
    std::vector<DebugDrawing> drawings(bool truth) const;

private:
    std::vector<std::unique_ptr<PerceptEntry>> m_entries;
    std::size_t m_present_count = 0;
};

/// The layer ids drawings() gives for `kinds` (detections, or truth).
std::vector<std::string> perceptLayerIds(const std::vector<const PerceptKind*>& kinds, bool truth);

} // namespace fieldsight
