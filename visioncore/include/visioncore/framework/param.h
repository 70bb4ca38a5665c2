// Stage parameters: each declared once, as a typed member of its stage, with what an editor needs.
#pragma once

#include "visioncore/basics/colour.h"
#include "visioncore/basics/result.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace fieldsight {

class Stage;

/// What kind of editor a parameter wants.
enum class ParamKind {
    Real,    ///< any number in [min, max]
    Integer, ///< whole numbers in [min, max]
    Boolean, ///< 0 or 1
    Choice,  ///< one of `choices` (a colour class, for example)
};

std::string_view paramKindName(ParamKind kind); ///< "real", "integer", "boolean", "choice"

/// The frame width a length parameter is given for. A parameter whose unit is "px" is a length in
/// a frame this wide: a stage running on a frame `width` pixels wide reads it multiplied by
/// width / kParamReferenceWidth (x4 at 1280x720), so the defaults suit every frame size and a value
/// set once suits a stream at any size. At 320 wide the factor is exactly 1.
inline constexpr int kParamReferenceWidth = 320;

/// One allowed value of a Choice parameter.
struct ParamChoice
{
    int value = 0;
    std::string name; ///< e.g. "yellow"
};

/// A parameter as a host sees it: enough to build an editor with a "reset to default".
struct ParamInfo
{
    std::string name; ///< snake_case, unique within the stage
    ParamKind kind = ParamKind::Real;
    std::string unit; ///< "px", "rad", "" for counts and ratios
    /// Unit "px": the value is for a frame kParamReferenceWidth wide and follows the frame's width.
    bool scales_with_width = false;
    std::string description; ///< one or two sentences for a user (a tooltip)
    double value = 0;        ///< current value
    double default_value = 0;
    double min = 0;
    double max = 0;
    double step = 1;                  ///< a sensible increment for a spin box or slider
    std::vector<ParamChoice> choices; ///< Choice only
    /// A setting of the scene a search may fit to annotations (`fieldsight tune`); false for
    /// one that measures nothing (a random seed), which fitting would only overfit.
    bool fitted = true;
};

/// Whether `value` suits `param` (range, whole numbers for integers and choices, a known choice);
/// the message names `stage_id`.`name`. ParamBase::set, ParamSet::check and
/// ControlWrapper::applyParams all judge values by this.
Status checkParamValue(const ParamInfo& param, std::string_view stage_id, double value);

/// How a parameter is declared, apart from its default (which has the parameter's own type).
struct ParamSpec
{
    const char* name = "";
    const char* unit = "";
    double min = 0;
    double max = 0;
    double step = 0; ///< 0: 1 for whole numbers, (max - min) / 100 for reals
    const char* description = "";
    bool fitted = true; ///< ParamInfo::fitted
};

/// The untyped side of a parameter, through which a stage lists and sets its parameters.
class ParamBase
{
public:
    ParamBase(const ParamBase&) = delete; // the stage keeps a pointer to it
    ParamBase& operator=(const ParamBase&) = delete;

    /// The info with the current value.
    ParamInfo info() const;
    const std::string& name() const { return m_info.name; }
    double get() const { return load(); } ///< as set, unscaled
    /// Checks `value` against the kind and range; the message names `stage_id`.`name`.
    Status set(std::string_view stage_id, double value);
    void reset() { store(m_info.default_value); }

protected:
    ParamBase(Stage* owner, ParamKind kind, double default_value, const ParamSpec& spec,
              std::vector<ParamChoice> choices = {});
    ~ParamBase() = default;
    virtual double load() const = 0;
    virtual void store(double value) = 0;
    /// What a length parameter is multiplied by for the frame being run (1 for other parameters).
    double scale() const { return m_scale ? *m_scale : 1.0; }
    double lowest() const { return m_info.min; } ///< a scaled length never goes below it

private:
    ParamInfo m_info;                ///< value unused; load() is the truth
    const double* m_scale = nullptr; ///< the owner's pixel scale, for "px" parameters
};

namespace detail {
template <class T> constexpr ParamKind paramKindOf()
{
    if constexpr (std::is_same_v<T, bool>)
        return ParamKind::Boolean;
    else if constexpr (std::is_same_v<T, Colour>)
        return ParamKind::Choice;
    else if constexpr (std::is_integral_v<T>)
        return ParamKind::Integer;
    else
        return ParamKind::Real;
}
std::vector<ParamChoice> colourChoices();
template <class T> constexpr double toDouble(T value)
{
    if constexpr (std::is_enum_v<T>)
        return double(std::underlying_type_t<T>(value));
    else
        return double(value);
}
} // namespace detail

/// A stage's parameter of type T (double, int, std::uint32_t, bool or Colour), declared as a
/// member with its default and spec, and read in the stage's code as a plain T:
///
///     Param<int> m_iterations{this, 100, {"iterations", "", 1, 10000, 1, "RANSAC samples."}};
///
/// A length (unit "px") reads as its value scaled to the frame being run (see
/// kParamReferenceWidth; a whole number is rounded; never below the parameter's range), so a
/// stage's code never scales by hand.
template <class T> class Param final : public ParamBase
{
    static_assert(std::is_same_v<T, double> || std::is_same_v<T, int> ||
                      std::is_same_v<T, std::uint32_t> || std::is_same_v<T, bool> ||
                      std::is_same_v<T, Colour>,
                  "a parameter is a double, int, std::uint32_t, bool or Colour");

public:
    Param(Stage* owner, T default_value, const ParamSpec& spec)
        : ParamBase(owner, detail::paramKindOf<T>(), detail::toDouble(default_value), spec,
                    std::is_same_v<T, Colour> ? detail::colourChoices()
                                              : std::vector<ParamChoice>{}),
          m_value(default_value)
    {
    }
    operator T() const { return value(); }
    /// As the stage uses it: a length scaled to the frame being run.
    T value() const
    {
        // Exactly m_value at the reference width; on a tiny frame never below the parameter's
        // range (a scan line spacing of 0 would never end).
        if constexpr (std::is_same_v<T, double>)
            return m_value < lowest() ? m_value : std::max(m_value * scale(), lowest());
        else if constexpr (std::is_same_v<T, int>)
            return m_value < lowest()
                       ? m_value
                       : std::max(int(std::lround(m_value * scale())), int(lowest()));
        else
            return m_value;
    }

private:
    double load() const override { return detail::toDouble(m_value); }
    void store(double value) override
    {
        if constexpr (std::is_same_v<T, bool>)
            m_value = value != 0;
        else if constexpr (std::is_enum_v<T>)
            m_value = T(std::underlying_type_t<T>(value));
        else
            m_value = static_cast<T>(value);
    }

    T m_value;
};

} // namespace fieldsight
