#pragma once
#include <volume_model/SpatialWeighting.h>

#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace volren {

/// What kind of value a parameter holds.
enum class ParameterType
{
    Number,   ///< a real number (double); NaN only where `emptyMeans` allows it
    Integer,  ///< a whole number (int)
    Switch,   ///< on or off (bool)
    Choice,   ///< one of `choices` (std::string, the choice's name)
    Curve,    ///< a weight curve (WeightCurve: "u:w,u:w,..." or "ramp:A")
};

/// A parameter's value: the alternative its ParameterType names.
using ParameterValue = std::variant<double, int, bool, std::string, WeightCurve>;

/// How the settings panel shows a parameter.
struct PanelHint
{
    enum Kind
    {
        Slider,     ///< linear slider over [lo, hi]
        LogSlider,  ///< logarithmic slider over [lo, hi] (lo > 0)
        Checkbox,   ///< Switch parameters
        Combo,      ///< Choice parameters
        Text,       ///< a line of text, applied with Enter (curves)
        Hidden,     ///< not shown
    };
    Kind kind = Slider;
    /// The slider's span, within the valid range (equal bounds: the valid range itself).
    double lo = 0.0, hi = 0.0;
};

/// One parameter of a shader-function implementation (or of all implementations of a slot),
/// declared beside the implementation's entry: what users set with `--set KEY=VALUE`, scene
/// files store, the panel shows and the implementation reads when it binds. Plain data.
struct ParameterDecl
{
    std::string key = {};  ///< the name users write (camelCase, unique across the registry)
    ParameterType type = ParameterType::Number;
    ParameterValue defaultValue = 0.0;  ///< of the alternative `type` names
    double lo = 0.0, hi = 0.0;          ///< Number, Integer: the valid range
    bool openLow = false;               ///< Number: lo itself is not valid
    std::vector<std::string> choices = {};  ///< Choice: the names, in order (their index also reads)
    /// Number: what empty text means (the value is then NaN, e.g. "the TF's first opaque value");
    /// empty: empty text is an error.
    std::string emptyMeans = {};
    std::string unit = {};  ///< unit of Number and Integer values ("voxels", "degrees"), or ""
    std::string help = {};  ///< one line for --help-settings and the panel's tooltip
    std::string label = {};  ///< the panel's label; empty: the key
    PanelHint panel = {};
    std::vector<std::string> aliases = {};  ///< other keys accepted (old names)
    std::string slot = {};                  ///< the slot of the implementations that read it (empty: a setting every volume has)
    /// The implementations of `slot` that read it; empty: every implementation of the slot.
    std::vector<std::string> implementations = {};

    /// Reads `text` as a value of this parameter; false with `error` naming the key, the value,
    /// the valid range or choices and the implementations that read it.
    bool parse(const std::string& text, ParameterValue& out, std::string& error) const;
    /// `value` as text that parse() reads back exactly (numbers as the shortest such text).
    std::string format(const ParameterValue& value) const;
    /// Whether `value` is of this parameter's type and within its range.
    bool valid(const ParameterValue& value) const;
    /// "in (0, 120] degrees", "one of a, b", ...: the valid values, for help and errors.
    std::string range() const;
    /// "Shadowing cone, cone_ao" / "Shading (every implementation)": who reads it.
    std::string owners() const;
    /// Number: whether every finite number is valid (lo and hi the extremes of double).
    bool unbounded() const;
    /// Whether implementation `name` of `slot` reads it.
    bool readBy(const std::string& slotName, const std::string& name) const;
    /// The same parameter as `o` (all but its implementations).
    bool sameAs(const ParameterDecl& o) const;
};

/// Whether two values are the same (NaN the same as NaN: "the scene decides" in both).
bool sameValue(const ParameterValue& a, const ParameterValue& b);

/// `key` in lower case (settings keys are matched without regard to case).
std::string lowerKey(std::string key);

}  // namespace volren
