#pragma once
#include <volume_model/TransferFunction.h>

#include <osg/Vec3d>
#include <osg/ref_ptr>

#include <string>
#include <utility>
#include <vector>

namespace volren {

/// A 3D Slicer volume property file (`.vp`, what Slicer's vtkMRMLVolumePropertyStorageNode
/// writes; docs/transfer-functions.md): nine lines, the first six one number each, the last
/// three a function "N x1 y1 x2 y2 ..." whose N counts the numbers after it. Plain data as read.
struct SlicerVolumeProperty
{
    using Curve = std::vector<std::pair<double, double>>;              ///< (x, y), x increasing
    using ColourCurve = std::vector<std::pair<double, osg::Vec3d>>;  ///< (value, rgb), value increasing

    int interpolationType = 1;  ///< line 1: VTK's voxel interpolation, 0 nearest, 1 linear
    bool shade = false;         ///< line 2: lighting on
    double diffuse = 0.7;       ///< line 3
    double ambient = 0.1;       ///< line 4
    double specular = 0.2;      ///< line 5
    double specularPower = 10;  ///< line 6
    Curve scalarOpacity;        ///< line 7: (data value, opacity)
    Curve gradientOpacity;      ///< line 8: (gradient magnitude, opacity); may be empty
    ColourCurve colour;         ///< line 9: (data value, r g b in [0,1])

    /// Whether the gradient opacity changes anything (it is present and not 1 everywhere).
    bool hasGradientOpacity() const;
    /// The scalar opacity and colour as one transfer function over data values (control points at
    /// the union of both curves' positions; both are linear between points, so nothing changes).
    osg::ref_ptr<TransferFunction> transferFunction() const;
};

/// Reads a `.vp` file strictly: wrong counts, numbers that are not finite, values outside [0,1],
/// decreasing positions, missing lines or extra non-blank lines are a std::runtime_error with
/// "file:line: reason". Repeated positions (steps) become strictly increasing as in Slicer: the
/// later point moves up to the next representable double. Blank lines 1-6 and 8 keep the defaults
/// (as Slicer's reader does); the opacity and colour lines are required.
SlicerVolumeProperty readSlicerVolumeProperty(const std::string& path);

}  // namespace volren
