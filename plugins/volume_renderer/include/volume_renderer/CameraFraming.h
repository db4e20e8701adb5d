#pragma once
#include <osg/BoundingBox>
#include <osg/Matrixd>
#include <osg/Node>
#include <osg/Vec3d>

#include <optional>
#include <vector>

namespace volren {

/// What a user asked of the camera; whatever is unset is chosen to frame the scene.
struct CameraRequest
{
    std::optional<osg::Vec3d> eye;       ///< eye position (world)
    std::optional<osg::Vec3d> center;    ///< point looked at (world)
    std::optional<osg::Vec3d> up;        ///< up vector (default +z)
    std::optional<double> fov;           ///< vertical field of view in degrees (default 30)
    bool orthographic = false;           ///< parallel projection
    std::optional<double> orthoHeight;   ///< visible height of a parallel projection (default: fitted)
    osg::Vec3d direction{0.55, 1.0, 0.35};  ///< from the scene towards the eye when `eye` is unset
    double margin = 0.03;                ///< fraction of the image left free on each side
};

/// A camera's view and projection matrices.
struct CameraView
{
    osg::Matrixd view;        ///< world to eye
    osg::Matrixd projection;  ///< eye to clip
};

/// Axis-aligned world box of what the scene shows: drawables and every VolumeNode's box, under
/// their transforms (lights and clip shapes add nothing). Invalid for an empty scene.
osg::BoundingBoxd sceneBoundingBox(const osg::Node& scene);

/// The view `request` asks for, with what it leaves open chosen so that all eight corners of
/// the scene's box lie inside the image (less `margin`), as tightly as the view direction
/// allows: perspective moves the eye along and across the view direction, orthographic fits the
/// height. `aspect` is width / height. Throws std::invalid_argument for a degenerate request
/// (eye equal to centre, up along the view direction).
CameraView frameScene(const osg::Node& scene, const CameraRequest& request, double aspect);

/// `frames` views on a circle around `axis` through the box centre (the first is frameScene's
/// direction), all at one distance (or ortho height) that fits the box in every one of them,
/// so a turntable neither pumps nor clips.
std::vector<CameraView> turntableViews(const osg::Node& scene, const CameraRequest& request, double aspect,
                                       const osg::Vec3d& axis, int frames);

}  // namespace volren
