#include <volume_model/TransferFunction.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace volren {

TransferFunction::TransferFunction() = default;

TransferFunction::TransferFunction(const TransferFunction& other, const osg::CopyOp& copyop)
    : osg::Object(other, copyop),
      _points(other._points),
      _hasDomain(other._hasDomain),
      _domainMin(other._domainMin),
      _domainMax(other._domainMax),
      _resolution(other._resolution),
      _interpolation(other._interpolation)
{
}

void TransferFunction::setPoint(double value, const osg::Vec4& rgba)
{
    if (!std::isfinite(value)) throw std::invalid_argument("transfer-function point value must be finite");
    for (int c = 0; c < 4; ++c)
        if (!(rgba[c] >= 0.0f && rgba[c] <= 1.0f))
            throw std::invalid_argument("transfer-function colour at value " + std::to_string(value) +
                                        " has component " + std::to_string(rgba[c]) + " outside [0,1]");
    _points[value] = rgba;
    ++_modifiedCount;
}

bool TransferFunction::removePoint(double value)
{
    if (_points.erase(value) == 0) return false;
    ++_modifiedCount;
    return true;
}

void TransferFunction::assign(const TransferFunction& other)
{
    _points = other._points;
    _hasDomain = other._hasDomain;
    _domainMin = other._domainMin;
    _domainMax = other._domainMax;
    _resolution = other._resolution;
    _interpolation = other._interpolation;
    ++_modifiedCount;
}

void TransferFunction::setInterpolation(Interpolation mode)
{
    if (mode == _interpolation) return;
    _interpolation = mode;
    ++_modifiedCount;
}

void TransferFunction::clearPoints()
{
    _points.clear();
    ++_modifiedCount;
}

void TransferFunction::setDomain(double minValue, double maxValue)
{
    if (!std::isfinite(minValue) || !std::isfinite(maxValue) || !(minValue < maxValue))
        throw std::invalid_argument("transfer-function domain needs finite min < max, got " +
                                    std::to_string(minValue) + ".." + std::to_string(maxValue));
    _hasDomain = true;
    _domainMin = minValue;
    _domainMax = maxValue;
    ++_modifiedCount;
}

void TransferFunction::clearDomain()
{
    _hasDomain = false;
    ++_modifiedCount;
}

double TransferFunction::domainMin() const
{
    if (_hasDomain || _points.empty()) return _domainMin;
    return _points.begin()->first;
}

double TransferFunction::domainMax() const
{
    if (_hasDomain || _points.empty()) return _domainMax;
    const double hi = _points.rbegin()->first;
    return hi > domainMin() ? hi : domainMin() + 1.0;  // a single point still spans a window
}

void TransferFunction::remap(double newMin, double newMax)
{
    if (!std::isfinite(newMin) || !std::isfinite(newMax) || !(newMin < newMax))
        throw std::invalid_argument("transfer-function remap needs finite min < max, got " + std::to_string(newMin) +
                                    ".." + std::to_string(newMax));
    const double lo = domainMin(), hi = domainMax();
    const double scale = (newMax - newMin) / (hi - lo);
    Points moved;
    for (const auto& [value, rgba] : _points) moved[newMin + (value - lo) * scale] = rgba;
    _points.swap(moved);
    if (_hasDomain) {
        _domainMin = newMin;
        _domainMax = newMax;
    }
    ++_modifiedCount;
}

void TransferFunction::setResolution(unsigned int entries)
{
    if (entries < 2 || entries > 65536)
        throw std::invalid_argument("transfer-function resolution must be 2..65536, got " + std::to_string(entries));
    _resolution = entries;
    ++_modifiedCount;
}

osg::Vec4 TransferFunction::evaluate(double value) const
{
    if (_points.empty()) return osg::Vec4(0, 0, 0, 0);
    auto upper = _points.lower_bound(value);
    if (upper == _points.begin()) return upper->second;
    if (upper == _points.end()) return _points.rbegin()->second;
    if (upper->first == value) return upper->second;
    auto lower = std::prev(upper);
    const double h = upper->first - lower->first;
    const double t = (value - lower->first) / h;
    if (_interpolation == Interpolation::Linear) return lower->second * float(1.0 - t) + upper->second * float(t);

    // Monotone cubic Hermite (Fritsch-Carlson), per channel: tangents are the mean of the
    // neighbouring secants, zero at a local extremum or a flat segment, and limited so that the
    // curve stays between its points (no overshoot, so components stay in [0, 1]).
    const auto before = lower == _points.begin() ? _points.end() : std::prev(lower);
    const auto after = std::next(upper);
    const double h00 = (1.0 + 2.0 * t) * (1.0 - t) * (1.0 - t), h10 = t * (1.0 - t) * (1.0 - t);
    const double h01 = t * t * (3.0 - 2.0 * t), h11 = t * t * (t - 1.0);
    osg::Vec4 out;
    for (int c = 0; c < 4; ++c) {
        const double y0 = lower->second[c], y1 = upper->second[c];
        const double d = (y1 - y0) / h;
        auto tangent = [&](double neighbourSecant, bool exists) {
            if (!exists) return d;  // an end point: the segment's own secant
            return neighbourSecant * d > 0.0 ? 0.5 * (neighbourSecant + d) : 0.0;
        };
        double m0 = tangent(before != _points.end() ? (y0 - before->second[c]) / (lower->first - before->first) : 0.0,
                            before != _points.end());
        double m1 = tangent(after != _points.end() ? (after->second[c] - y1) / (after->first - upper->first) : 0.0,
                            after != _points.end());
        if (d == 0.0) {
            m0 = m1 = 0.0;
        } else {
            const double a = m0 / d, b = m1 / d;
            if (a < 0.0) m0 = 0.0;
            if (b < 0.0) m1 = 0.0;
            const double r = a * a + b * b;
            if (r > 9.0) {
                const double tau = 3.0 / std::sqrt(r);
                m0 = tau * a * d;
                m1 = tau * b * d;
            }
        }
        out[c] = float(std::clamp(h00 * y0 + h10 * h * m0 + h01 * y1 + h11 * h * m1, 0.0, 1.0));
    }
    return out;
}

std::vector<osg::Vec4> TransferFunction::lookupTable() const
{
    std::vector<osg::Vec4> table(_resolution);
    const double lo = domainMin(), hi = domainMax();
    for (unsigned int i = 0; i < _resolution; ++i)
        table[i] = evaluate(lo + (hi - lo) * double(i) / double(_resolution - 1));
    return table;
}

}  // namespace volren
