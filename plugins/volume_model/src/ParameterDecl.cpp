#include <volume_model/ParameterDecl.h>
#include <volume_model/ParseNumber.h>

#include <cmath>
#include <limits>
#include <sstream>

namespace volren {

std::string lowerKey(std::string key)
{
    for (char& c : key) c = char(std::tolower(static_cast<unsigned char>(c)));
    return key;
}

bool sameValue(const ParameterValue& a, const ParameterValue& b)
{
    const double *x = std::get_if<double>(&a), *y = std::get_if<double>(&b);
    return x && y ? *x == *y || (std::isnan(*x) && std::isnan(*y)) : a == b;
}

namespace {

std::string joined(const std::vector<std::string>& names)
{
    std::string out;
    for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
    return out;
}

}  // namespace

std::string ParameterDecl::owners() const
{
    return slot + (implementations.empty() ? " (every implementation)" : " " + joined(implementations));
}

bool ParameterDecl::unbounded() const
{
    return lo <= std::numeric_limits<double>::lowest() && hi >= std::numeric_limits<double>::max();
}

bool ParameterDecl::readBy(const std::string& slotName, const std::string& name) const
{
    if (slotName != slot) return false;
    if (implementations.empty()) return name != "null";
    for (const std::string& i : implementations)
        if (i == name) return true;
    return false;
}

bool ParameterDecl::sameAs(const ParameterDecl& o) const
{
    return key == o.key && type == o.type && sameValue(defaultValue, o.defaultValue) && lo == o.lo && hi == o.hi &&
           openLow == o.openLow && choices == o.choices && emptyMeans == o.emptyMeans && unit == o.unit &&
           help == o.help && label == o.label && panel.kind == o.panel.kind && panel.lo == o.panel.lo &&
           panel.hi == o.panel.hi && aliases == o.aliases && slot == o.slot;
}

std::string ParameterDecl::range() const
{
    std::ostringstream out;
    switch (type) {
    case ParameterType::Number:
        if (unbounded()) return "any number";
        out << "in " << (openLow ? "(" : "[") << lo << ", " << hi << "]";
        break;
    case ParameterType::Integer:
        out << "in [" << int(lo) << ", " << int(hi) << "]";
        break;
    case ParameterType::Switch:
        return "on or off";
    case ParameterType::Choice:
        return "one of " + joined(choices);
    case ParameterType::Curve:
        return "a curve 'u:w,u:w,...' (u in [0,1] increasing, w in [0,1]), 'ramp:A' or none";
    }
    if (!unit.empty()) out << " " << unit;
    return out.str();
}

bool ParameterDecl::valid(const ParameterValue& value) const
{
    switch (type) {
    case ParameterType::Number: {
        const double* v = std::get_if<double>(&value);
        if (!v) return false;
        if (std::isnan(*v)) return !emptyMeans.empty();
        return (openLow ? *v > lo : *v >= lo) && *v <= hi;
    }
    case ParameterType::Integer: {
        const int* v = std::get_if<int>(&value);
        return v && *v >= lo && *v <= hi;
    }
    case ParameterType::Switch:
        return std::holds_alternative<bool>(value);
    case ParameterType::Choice: {
        const std::string* v = std::get_if<std::string>(&value);
        if (!v) return false;
        for (const std::string& c : choices)
            if (c == *v) return true;
        return false;
    }
    case ParameterType::Curve:
        return std::holds_alternative<WeightCurve>(value);
    }
    return false;
}

bool ParameterDecl::parse(const std::string& text, ParameterValue& out, std::string& error) const
{
    const std::string who = slot.empty() ? "" : " (read by " + owners() + ")";
    double v = 0.0;
    switch (type) {
    case ParameterType::Number:
        if (text.empty() && !emptyMeans.empty()) return out = std::nan(""), true;
        if (!parseFiniteNumber(text, v) || !valid(v))
            return error = key + " must be a number" + (unbounded() ? "" : " " + range()) + ", got '" + text + "'" + who,
                   false;
        return out = v, true;
    case ParameterType::Integer:
        if (!parseFiniteNumber(text, v) || v != std::floor(v) || v < lo || v > hi)
            return error = key + " must be a whole number " + range() + ", got '" + text + "'" + who, false;
        return out = int(v), true;
    case ParameterType::Switch: {
        const std::string b = lowerKey(text);
        if (b == "on" || b == "true" || b == "1") return out = true, true;
        if (b == "off" || b == "false" || b == "0") return out = false, true;
        return error = key + " must be on or off, got '" + text + "'" + who, false;
    }
    case ParameterType::Choice:
        for (std::size_t i = 0; i < choices.size(); ++i)
            if (lowerKey(text) == lowerKey(choices[i]) || text == std::to_string(i)) return out = choices[i], true;
        return error = key + " must be " + range() + "; got '" + text + "'" + who, false;
    case ParameterType::Curve: {
        WeightCurve curve;
        std::string why;
        if (!WeightCurve::parse(text, curve, why)) return error = key + ": " + why + who, false;
        return out = curve, true;
    }
    }
    return error = key + ": unknown parameter type", false;
}

std::string ParameterDecl::format(const ParameterValue& value) const
{
    if (const double* v = std::get_if<double>(&value)) return std::isnan(*v) ? std::string() : shortestText(*v);
    if (const int* v = std::get_if<int>(&value)) return std::to_string(*v);
    if (const bool* v = std::get_if<bool>(&value)) return *v ? "on" : "off";
    if (const std::string* v = std::get_if<std::string>(&value)) return *v;
    return std::get<WeightCurve>(value).text();
}

}  // namespace volren
