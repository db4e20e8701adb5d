#pragma once
// Internal to volume_model: the piecewise-linear curves of TF preset files (ParaView, Slicer).
#include <volume_model/TransferFunction.h>

#include <iterator>
#include <map>

namespace volren {

/// Piecewise-linear function through (x, y) pairs, constant beyond the ends (VTK's clamping).
inline double piecewiseLinear(const std::map<double, double>& f, double x)
{
    auto upper = f.lower_bound(x);
    if (upper == f.begin()) return upper->second;
    if (upper == f.end()) return f.rbegin()->second;
    auto lower = std::prev(upper);
    const double t = (x - lower->first) / (upper->first - lower->first);
    return lower->second + t * (upper->second - lower->second);
}

/// A TF of four piecewise-linear curves (r, g, b, opacity over data values): control points at
/// the union of their positions give exactly the same function.
inline osg::ref_ptr<TransferFunction> transferFunctionFromCurves(const std::map<double, double> (&channel)[4])
{
    osg::ref_ptr<TransferFunction> tf = new TransferFunction;
    for (const auto& ch : channel)
        for (const auto& point : ch) {
            const double x = point.first;
            tf->setPoint(x, osg::Vec4(float(piecewiseLinear(channel[0], x)), float(piecewiseLinear(channel[1], x)),
                                      float(piecewiseLinear(channel[2], x)), float(piecewiseLinear(channel[3], x))));
        }
    return tf;
}

}  // namespace volren
