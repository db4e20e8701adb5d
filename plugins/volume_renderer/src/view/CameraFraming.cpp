#include <volume_renderer/Annotations.h>
#include <volume_renderer/CameraFraming.h>

#include <volume_model/VolumeNode.h>

#include <osg/ComputeBoundsVisitor>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace volren {

namespace {

/// ComputeBoundsVisitor that also counts VolumeNode boxes (they have no drawables) and leaves
/// out screen annotations (drawn in pixels).
class SceneBounds : public osg::ComputeBoundsVisitor
{
public:
    void apply(osg::Node& node) override
    {
        if (dynamic_cast<Annotations*>(&node)) return;
        if (auto* volume = dynamic_cast<VolumeNode*>(&node)) {
            const osg::BoundingBox box = volume->localBox();
            if (box.valid()) {
                const osg::Matrix m = _matrixStack.empty() ? osg::Matrix() : _matrixStack.back();
                for (int c = 0; c < 8; ++c) _bb.expandBy(box.corner(c) * m);
            }
            return;
        }
        traverse(node);
    }
};

/// The orthonormal eye basis looking along `forward` with `up` as close to up as it can be.
struct Basis
{
    osg::Vec3d right, up, forward;
};

Basis basis(const osg::Vec3d& forwardIn, const osg::Vec3d& upIn)
{
    Basis b;
    b.forward = forwardIn;
    b.forward.normalize();
    b.right = b.forward ^ upIn;
    if (b.right.length() < 1e-12 * upIn.length()) throw std::invalid_argument("the up vector is parallel to the view direction");
    b.right.normalize();
    b.up = b.right ^ b.forward;
    return b;
}

/// The scene's box corners relative to `centre` in the basis (x right, y up, z forward).
std::vector<osg::Vec3d> cornersIn(const osg::BoundingBoxd& box, const osg::Vec3d& centre, const Basis& b)
{
    std::vector<osg::Vec3d> out;
    for (int c = 0; c < 8; ++c) {
        const osg::Vec3d p = box.corner(c) - centre;
        out.emplace_back(p * b.right, p * b.up, p * b.forward);
    }
    return out;
}

/// Distance along the view and sideways shift (ex, ey) of a perspective eye that fits the
/// corners inside half-extents tx, ty (tangents); with `fixedCentre` the eye is not shifted.
osg::Vec3d fitPerspective(const std::vector<osg::Vec3d>& corners, double tx, double ty, bool fixedCentre)
{
    auto fit = [&](int axis, double t, double& shift) {
        double a = -1e300, b = -1e300;  // the farthest the eye must be for the +side and -side
        for (const osg::Vec3d& p : corners) {
            a = std::max(a, p[axis] / t - p.z());
            b = std::max(b, -p[axis] / t - p.z());
        }
        if (fixedCentre) {
            shift = 0.0;
            return std::max(a, b);
        }
        shift = t * (a - b) * 0.5;
        return (a + b) * 0.5;
    };
    double ex = 0.0, ey = 0.0;
    const double dx = fit(0, tx, ex), dy = fit(1, ty, ey);
    double d = std::max(dx, dy);
    double zMin = 1e300, size = 0.0;
    for (const osg::Vec3d& p : corners) {
        zMin = std::min(zMin, p.z());
        size = std::max(size, p.length());
    }
    d = std::max(d, -zMin + 1e-6 * std::max(size, 1e-12));  // a flat box seen edge-on
    return {ex, ey, d};
}

/// Sideways shift (ex, ey) and visible height of a parallel projection that fits the corners.
osg::Vec3d fitOrthographic(const std::vector<osg::Vec3d>& corners, double aspect, double fill, bool fixedCentre)
{
    osg::Vec3d lo(1e300, 1e300, 1e300), hi(-1e300, -1e300, -1e300);
    for (const osg::Vec3d& p : corners)
        for (int i = 0; i < 3; ++i) {
            lo[i] = std::min(lo[i], p[i]);
            hi[i] = std::max(hi[i], p[i]);
        }
    if (fixedCentre) {
        const double halfX = std::max(std::abs(lo.x()), std::abs(hi.x()));
        const double halfY = std::max(std::abs(lo.y()), std::abs(hi.y()));
        return {0.0, 0.0, 2.0 * std::max(halfY, halfX / aspect) / fill};
    }
    const double height = std::max(hi.y() - lo.y(), (hi.x() - lo.x()) / aspect) / fill;
    return {(hi.x() + lo.x()) * 0.5, (hi.y() + lo.y()) * 0.5, height};
}

osg::BoundingBoxd boxOrUnit(const osg::Node& scene)
{
    osg::BoundingBoxd box = sceneBoundingBox(scene);
    if (!box.valid()) box.set(-1, -1, -1, 1, 1, 1);
    return box;
}

/// The projection, its near and far planes around the scene's depth range [nearest, farthest]
/// from the eye (OSG narrows them to what is drawn each frame by rescaling this projection's
/// depth: planes fixed at 0.01 and 1e6 lost that rescaling to double rounding once the scene lay
/// ~1e13 units away, and nothing was drawn).
osg::Matrixd projectionFor(const CameraRequest& request, double aspect, double orthoHeight, double nearest, double farthest)
{
    const double extent = std::max(farthest - nearest, 1e-300);
    if (request.orthographic) {
        const double h = orthoHeight * 0.5;
        return osg::Matrixd::ortho(-h * aspect, h * aspect, -h, h, nearest - extent, farthest + extent);
    }
    const double zFar = std::max(farthest + extent, extent);
    const double zNear = nearest > 0.0 ? 0.5 * nearest : zFar * 1e-6;  // the eye inside the box
    return osg::Matrixd::perspective(request.fov.value_or(30.0), aspect, zNear, zFar);
}

/// Tangents of the half-angles the box may fill, margin taken off.
std::pair<double, double> halfTangents(const CameraRequest& request, double aspect)
{
    const double fill = 1.0 - 2.0 * request.margin;
    const double ty = std::tan(osg::DegreesToRadians(request.fov.value_or(30.0) * 0.5));
    return {ty * aspect * fill, ty * fill};
}

void check(const CameraRequest& request, double aspect)
{
    if (!(aspect > 0.0) || !std::isfinite(aspect)) throw std::invalid_argument("the image aspect ratio must be positive");
    if (!(request.margin >= 0.0 && request.margin < 0.5)) throw std::invalid_argument("the framing margin must be in [0, 0.5)");
    if (request.eye && request.center && (*request.eye - *request.center).length() == 0.0)
        throw std::invalid_argument("the eye and the centre must differ");
}

}  // namespace

osg::BoundingBoxd sceneBoundingBox(const osg::Node& scene)
{
    SceneBounds bounds;
    const_cast<osg::Node&>(scene).accept(bounds);
    const osg::BoundingBox& b = bounds.getBoundingBox();
    return b.valid() ? osg::BoundingBoxd(b._min, b._max) : osg::BoundingBoxd();
}

CameraView frameScene(const osg::Node& scene, const CameraRequest& request, double aspect)
{
    check(request, aspect);
    const osg::BoundingBoxd box = boxOrUnit(scene);
    const osg::Vec3d centre = request.center.value_or(box.center());
    const osg::Vec3d up = request.up.value_or(osg::Vec3d(0, 0, 1));
    const osg::Vec3d towardEye = request.eye ? *request.eye - centre : request.direction;
    if (towardEye.length() == 0.0) throw std::invalid_argument("the eye and the centre must differ");
    const Basis b = basis(-towardEye, up);
    const std::vector<osg::Vec3d> corners = cornersIn(box, centre, b);
    const double fill = 1.0 - 2.0 * request.margin;

    CameraView view;
    osg::Vec3d eye, target;
    double orthoHeight = request.orthoHeight.value_or(1.0);
    if (request.orthographic) {
        const osg::Vec3d fit = fitOrthographic(corners, aspect, fill, request.center.has_value());
        if (!request.orthoHeight) orthoHeight = fit.z();
        target = request.eye || request.orthoHeight ? centre : centre + b.right * fit.x() + b.up * fit.y();
        double depth = 0.0;  // behind every corner
        for (const osg::Vec3d& p : corners) depth = std::max(depth, std::max(-p.z(), p.length()));
        eye = request.eye ? *request.eye : target - b.forward * (2.0 * depth + orthoHeight);
    } else if (request.eye) {
        eye = *request.eye;
        target = centre;
    } else {
        const auto [tx, ty] = halfTangents(request, aspect);
        const osg::Vec3d fit = fitPerspective(corners, tx, ty, request.center.has_value());
        target = centre + b.right * fit.x() + b.up * fit.y();
        eye = target - b.forward * fit.z();
    }
    view.view = osg::Matrixd::lookAt(eye, target, b.up);
    osg::Vec3d forward = target - eye;
    forward.normalize();
    double nearest = 1e300, farthest = -1e300;  // the box's depth range from the eye
    for (unsigned int i = 0; i < 8; ++i) {
        const double d = (box.corner(i) - eye) * forward;
        nearest = std::min(nearest, d);
        farthest = std::max(farthest, d);
    }
    view.projection = projectionFor(request, aspect, orthoHeight, nearest, farthest);
    return view;
}

std::vector<CameraView> turntableViews(const osg::Node& scene, const CameraRequest& request, double aspect,
                                       const osg::Vec3d& axis, int frames)
{
    check(request, aspect);
    if (frames < 1) throw std::invalid_argument("a turntable needs at least one frame");
    if (axis.length() == 0.0) throw std::invalid_argument("the turntable axis must not be zero");
    const osg::BoundingBoxd box = boxOrUnit(scene);
    const osg::Vec3d centre = request.center.value_or(box.center());
    const osg::Vec3d up = request.up.value_or(axis);
    const osg::Vec3d start = request.eye ? *request.eye - centre : request.direction;
    if (start.length() == 0.0) throw std::invalid_argument("the eye and the centre must differ");

    std::vector<osg::Vec3d> directions;
    for (int k = 0; k < frames; ++k) {
        osg::Vec3d d = osg::Matrixd::rotate(2.0 * osg::PI * k / frames, axis).preMult(start);
        d.normalize();
        directions.push_back(d);
    }
    // One distance (or height) for all: the largest any frame needs, about the fixed centre.
    double distance = request.eye ? start.length() : 0.0;
    double orthoHeight = request.orthoHeight.value_or(0.0);
    const double fill = 1.0 - 2.0 * request.margin;
    for (const osg::Vec3d& d : directions) {
        const Basis b = basis(-d, up);
        const std::vector<osg::Vec3d> corners = cornersIn(box, centre, b);
        if (request.orthographic && !request.orthoHeight)
            orthoHeight = std::max(orthoHeight, fitOrthographic(corners, aspect, fill, true).z());
        if (!request.orthographic && !request.eye) {
            const auto [tx, ty] = halfTangents(request, aspect);
            distance = std::max(distance, fitPerspective(corners, tx, ty, true).z());
        }
    }
    if (request.orthographic && !request.eye) distance = 2.0 * (box._max - box._min).length() + orthoHeight;

    // One projection for all: the depth range of the box's bounding sphere from the eye.
    const double radius = 0.5 * (box._max - box._min).length() + (box.center() - centre).length();
    const osg::Matrixd projection = projectionFor(request, aspect, orthoHeight, distance - radius, distance + radius);
    std::vector<CameraView> views;
    for (const osg::Vec3d& d : directions) {
        const Basis b = basis(-d, up);
        views.push_back({osg::Matrixd::lookAt(centre + d * distance, centre, b.up), projection});
    }
    return views;
}

}  // namespace volren
