#pragma once
#include <osg/Object>
#include <osg/Vec4>

#include <map>
#include <vector>

namespace volren {

/// Maps data values to RGBA through control points, piecewise linear or smooth (monotone cubic).
/// Colour is unassociated emission; alpha is the opacity of a segment as long as the
/// smallest voxel spacing of the volume it classifies (see DESIGN.md conventions).
class TransferFunction : public osg::Object
{
public:
    TransferFunction();
    TransferFunction(const TransferFunction& other, const osg::CopyOp& copyop = osg::CopyOp::SHALLOW_COPY);
    META_Object(volren, TransferFunction)

    using Points = std::map<double, osg::Vec4>;

    /// Sets (or replaces) the control point at data value `value`; components must lie in [0,1].
    void setPoint(double value, const osg::Vec4& rgba);
    /// Removes the control point at exactly `value`; returns false when there is none.
    bool removePoint(double value);
    /// Takes over points, domain, resolution and interpolation of `other` (an edit: bumps the
    /// modified count).
    void assign(const TransferFunction& other);
    /// Removes every control point.
    void clearPoints();
    /// Control points ordered by data value.
    const Points& points() const { return _points; }

    /// Value window mapped onto the lookup table; [first point, last point] when unset.
    void setDomain(double minValue, double maxValue);
    /// Forgets an explicit domain, so the control points' span is used.
    void clearDomain();
    /// Whether setDomain() set the window (rather than the points' span).
    bool hasExplicitDomain() const { return _hasDomain; }
    double domainMin() const;  ///< data value of the first lookup-table entry
    double domainMax() const;  ///< data value of the last lookup-table entry

    /// Moves the points (and an explicit domain) linearly so that [domainMin, domainMax] becomes
    /// [newMin, newMax]: a preset made for another value range applied to this data.
    void remap(double newMin, double newMax);

    /// Number of lookup-table entries (2 .. 65536, default 1024).
    void setResolution(unsigned int entries);
    unsigned int resolution() const { return _resolution; }  ///< lookup-table entries

    /// How channels run between control points.
    enum class Interpolation
    {
        Linear,         ///< straight segments (the default; OSG's `.tf` meaning)
        MonotoneCubic,  ///< smooth (C1) curves that never overshoot their points (Fritsch-Carlson)
    };
    void setInterpolation(Interpolation mode);
    Interpolation interpolation() const { return _interpolation; }  ///< between control points

    /// RGBA at data value `value`: interpolated between points, the end points' colour outside.
    osg::Vec4 evaluate(double value) const;
    /// resolution() entries; entry i is evaluate(domainMin + i/(resolution-1) * (domainMax - domainMin)).
    std::vector<osg::Vec4> lookupTable() const;

    /// Incremented on every change; the renderer re-uploads when it differs from its copy.
    unsigned int modifiedCount() const { return _modifiedCount; }

private:
    Points _points;
    bool _hasDomain = false;
    double _domainMin = 0.0, _domainMax = 1.0;
    unsigned int _resolution = 1024;
    Interpolation _interpolation = Interpolation::Linear;
    unsigned int _modifiedCount = 0;
};

}  // namespace volren
