#include <volume_model/ParseNumber.h>
#include <volume_model/RenderSettings.h>
#include <volume_model/SpatialWeighting.h>

#include <charconv>
#include <sstream>

namespace volren {

namespace {

std::string trimmed(const std::string& s)
{
    const auto first = s.find_first_not_of(" \t");
    if (first == std::string::npos) return {};
    return s.substr(first, s.find_last_not_of(" \t") - first + 1);
}

}  // namespace

double WeightCurve::operator()(double u) const
{
    if (knots.empty()) return 1.0;
    if (!(u > knots.front().first)) return knots.front().second;  // NaN too: the first weight
    for (std::size_t i = 1; i < knots.size(); ++i)
        if (u <= knots[i].first) {
            const auto& [u0, w0] = knots[i - 1];
            const auto& [u1, w1] = knots[i];
            return w0 + (u - u0) / (u1 - u0) * (w1 - w0);
        }
    return knots.back().second;
}

bool WeightCurve::identity() const
{
    for (const auto& knot : knots)
        if (knot.second != 1.0) return false;
    return true;
}

std::string WeightCurve::text() const
{
    std::string out;
    for (const auto& [u, w] : knots) out += (out.empty() ? "" : ",") + shortestText(u) + ":" + shortestText(w);
    return out;
}

bool WeightCurve::parse(const std::string& text, WeightCurve& out, std::string& error)
{
    const std::string t = trimmed(text);
    if (t.empty() || t == "none") return out.knots.clear(), true;
    if (t.rfind("ramp:", 0) == 0) {
        double a = 0.0;
        if (!parseFiniteNumber(t.substr(5), a) || !(a > 0.0) || a > 0.5)
            return error = "ramp:A needs 0 < A <= 0.5 (the fraction of the axis each end fades over), got '" + text + "'",
                   false;
        out.knots = a == 0.5 ? std::vector<std::pair<double, double>>{{0.0, 0.0}, {0.5, 1.0}, {1.0, 0.0}}
                             : std::vector<std::pair<double, double>>{{0.0, 0.0}, {a, 1.0}, {1.0 - a, 1.0}, {1.0, 0.0}};
        return true;
    }
    std::vector<std::pair<double, double>> knots;
    std::stringstream list(t);
    std::string item;
    while (std::getline(list, item, ',')) {
        const auto colon = item.find(':');
        double u = 0.0, w = 0.0;
        if (colon == std::string::npos || !parseFiniteNumber(trimmed(item.substr(0, colon)), u) ||
            !parseFiniteNumber(trimmed(item.substr(colon + 1)), w))
            return error = "a weight curve is 'u:w,u:w,...' or 'ramp:A'; '" + trimmed(item) + "' is not u:w", false;
        if (u < 0.0 || u > 1.0) return error = "knot '" + trimmed(item) + "': u must be in [0, 1]", false;
        if (w < 0.0 || w > 1.0) return error = "knot '" + trimmed(item) + "': the weight must be in [0, 1]", false;
        if (!knots.empty() && !(u > knots.back().first))
            return error = "knot '" + trimmed(item) + "': u must increase from knot to knot", false;
        knots.emplace_back(u, w);
    }
    if (knots.size() > maxKnots)
        return error = "a weight curve has at most " + std::to_string(maxKnots) + " knots, got " +
                       std::to_string(knots.size()),
               false;
    out.knots = std::move(knots);
    return true;
}

SpatialWeighting spatialWeighting(const RenderSettings& settings)
{
    SpatialWeighting w;
    for (std::size_t axis = 0; axis < 3; ++axis)
        w.axes[axis] = settings.parameter<WeightCurve>(std::string("weight") + "XYZ"[axis]);
    return w;
}

}  // namespace volren
