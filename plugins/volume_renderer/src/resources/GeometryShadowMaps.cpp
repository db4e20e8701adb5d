// Shadow maps of the opaque geometry: per light an orthographic (directional) or perspective
// (point) view from the light fitted to the receivers' box, its depth drawn by a pre-render
// camera that traverses the VolumeScene's children.
#include "GeometryShadowMaps.h"

#include <volume_renderer/CompositionPolicy.h>

#include <osg/ColorMask>
#include <osg/Geometry>
#include <osg/Notify>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>

namespace volren {

namespace {

/// Traverses a VolumeScene's children (not the scene's own cull, which would draw its volumes)
/// under the map camera.
class DrawSceneChildren : public osg::NodeCallback
{
public:
    osg::observer_ptr<osg::Group> scene;
    void operator()(osg::Node*, osg::NodeVisitor* nv) override
    {
        osg::ref_ptr<osg::Group> s;
        if (scene.lock(s)) s->osg::Group::traverse(*nv);
    }
};

/// What the maps' depth depends on below a scene's children: each drawable the active children
/// reach (under the traversal mask), its accumulated matrix, and for geometry the identity and
/// dirty() count of its vertex array and primitive sets (other drawables: their bounds). State
/// that changes depth otherwise (a polygon mode, an LOD switched by distance) is not seen.
class CasterSignature : public osg::NodeVisitor
{
public:
    std::vector<std::uint64_t> values;

    explicit CasterSignature(osg::Node::NodeMask mask) : osg::NodeVisitor(TRAVERSE_ACTIVE_CHILDREN)
    {
        setTraversalMask(mask);
    }

    void apply(osg::Transform& t) override
    {
        const osg::Matrixd outer = _matrix;
        t.computeLocalToWorldMatrix(_matrix, this);
        traverse(t);
        _matrix = outer;
    }

    void apply(osg::Drawable& d) override
    {
        values.push_back(reinterpret_cast<std::uintptr_t>(&d));
        for (int i = 0; i < 16; ++i) add(_matrix.ptr()[i]);
        if (const osg::Geometry* g = d.asGeometry()) {
            const osg::Array* vertices = g->getVertexArray();
            values.push_back(reinterpret_cast<std::uintptr_t>(vertices));
            values.push_back(vertices ? vertices->getModifiedCount() : 0);
            for (const osg::ref_ptr<osg::PrimitiveSet>& p : g->getPrimitiveSetList()) {
                values.push_back(reinterpret_cast<std::uintptr_t>(p.get()));
                values.push_back(p ? p->getModifiedCount() : 0);
            }
        } else {
            const osg::BoundingBox& b = d.getBoundingBox();
            for (int i = 0; i < 3; ++i) add(b._min[i]), add(b._max[i]);
        }
    }

private:
    osg::Matrixd _matrix;

    void add(double v)
    {
        std::uint64_t bits;
        std::memcpy(&bits, &v, sizeof bits);
        values.push_back(bits);
    }
};

/// A unit vector perpendicular to `d`.
osg::Vec3d perpendicular(const osg::Vec3d& d)
{
    osg::Vec3d p = std::abs(d.x()) < 0.9 ? d ^ osg::Vec3d(1, 0, 0) : d ^ osg::Vec3d(0, 1, 0);
    p.normalize();
    return p;
}

/// The view and projection of a map from `light` over `receivers`, with casters anywhere in
/// `casters` (a sphere holding the scene); false when no single frustum covers the receivers.
bool lightFrustum(const LightInfo& light, const osg::BoundingBoxd& receivers, const osg::BoundingSphered& casters,
                  osg::Matrixd& view, osg::Matrixd& projection)
{
    const osg::Vec3d centre = receivers.center();
    std::array<osg::Vec3d, 8> corners;
    for (int i = 0; i < 8; ++i) corners[std::size_t(i)] = receivers.corner(unsigned(i));
    const double reach = std::max(casters.radius() + (casters.center() - centre).length(), receivers.radius());
    if (light.position.w() == 0.0) {
        osg::Vec3d towards(light.position.x(), light.position.y(), light.position.z());
        towards.normalize();
        const osg::Vec3d eye = centre + towards * (2.0 * reach);  // beyond every caster
        view = osg::Matrixd::lookAt(eye, centre, perpendicular(towards));
        double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300, far = 0.0;
        for (const osg::Vec3d& c : corners) {
            const osg::Vec3d v = c * view;
            x0 = std::min(x0, v.x()), x1 = std::max(x1, v.x()), y0 = std::min(y0, v.y()), y1 = std::max(y1, v.y());
            far = std::max(far, -v.z());
        }
        projection = osg::Matrixd::ortho(x0, x1, y0, y1, 0.0, far * 1.0001);
        return true;
    }
    const osg::Vec3d eye(light.position.x(), light.position.y(), light.position.z());
    osg::Vec3d forward = centre - eye;
    if (!(forward.length() > 0.0)) return false;
    forward.normalize();
    view = osg::Matrixd::lookAt(eye, centre, perpendicular(forward));
    double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300, nearest = 1e300, far = 0.0;
    for (const osg::Vec3d& c : corners) {
        const osg::Vec3d v = c * view;
        const double depth = -v.z();
        if (!(depth > 1e-6 * receivers.radius())) return false;  // the light is beside or inside the box
        x0 = std::min(x0, v.x() / depth), x1 = std::max(x1, v.x() / depth);
        y0 = std::min(y0, v.y() / depth), y1 = std::max(y1, v.y() / depth);
        nearest = std::min(nearest, depth), far = std::max(far, depth);
    }
    // Near: where the casters' sphere begins (all casters behind it), else a small fraction of
    // the nearest receiver's distance.
    const double sphereNear = (casters.center() - eye).length() - casters.radius();
    const double near = std::clamp(sphereNear, 1e-3 * nearest, nearest * 0.999);
    projection = osg::Matrixd::frustum(x0 * near, x1 * near, y0 * near, y1 * near, near, far * 1.0001);
    return true;
}

}  // namespace

GeometryShadowMaps::GeometryShadowMaps() : _texture(new osg::Texture2DArray)
{
    _texture->setInternalFormat(GL_DEPTH_COMPONENT32F);
    _texture->setSourceFormat(GL_DEPTH_COMPONENT);
    _texture->setSourceType(GL_FLOAT);
    _texture->setFilter(osg::Texture::MIN_FILTER, osg::Texture::NEAREST);  // compared in the shader
    _texture->setFilter(osg::Texture::MAG_FILTER, osg::Texture::NEAREST);
    _texture->setWrap(osg::Texture::WRAP_S, osg::Texture::CLAMP_TO_BORDER);
    _texture->setWrap(osg::Texture::WRAP_T, osg::Texture::CLAMP_TO_BORDER);
    _texture->setWrap(osg::Texture::WRAP_R, osg::Texture::CLAMP_TO_EDGE);  // OSG's default CLAMP is not core GL
    _texture->setBorderColor(osg::Vec4d(1, 1, 1, 1));
    _texture->setTextureSize(size, size, 1);
}

void GeometryShadowMaps::cull(osgUtil::CullVisitor& cv, osg::Group& scene, const std::vector<LightInfo>& lights,
                              const osg::BoundingBoxd& receivers)
{
    // Volumes use the scene's first CompositionPolicy::maxLights lights (the analysis says so).
    const std::size_t n = std::min<std::size_t>(lights.size(), CompositionPolicy::maxLights);
    const osg::Matrixd zero(0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0);
    _matrices.assign(n, zero);
    if (n == 0 || !receivers.valid()) return;
    if (_texture->getTextureDepth() != int(n)) {  // layers for these lights; the cameras attach anew
        _texture->setTextureSize(size, size, int(n));
        _texture->dirtyTextureObject();
        _cameras.clear();
        _drawnFrom.clear();
    }
    // A layer is drawn again where its frustum or the casters changed, or where this context
    // holds no map yet (its first frame, or a new context after one was closed).
    CasterSignature signature(cv.getTraversalMask());
    for (unsigned int i = 0; i < scene.getNumChildren(); ++i) scene.getChild(i)->accept(signature);
    const bool castersChanged = signature.values != _casters;
    if (castersChanged) _casters = std::move(signature.values);
    const bool unmapped = !_texture->getTextureObject(cv.getState() ? cv.getState()->getContextID() : 0);
    if (castersChanged || unmapped) _drawnFrom.clear();
    _drawnFrom.resize(n, zero);
    osg::BoundingSphered casters;
    if (const osg::BoundingSphere& b = scene.getBound(); b.valid()) casters.set(osg::Vec3d(b.center()), b.radius());
    casters.expandBy(receivers);
    while (_cameras.size() < n) {
        osg::ref_ptr<osg::Camera> camera = new osg::Camera;
        camera->setRenderTargetImplementation(osg::Camera::FRAME_BUFFER_OBJECT);
        camera->setRenderOrder(osg::Camera::PRE_RENDER);
        camera->setReferenceFrame(osg::Camera::ABSOLUTE_RF);
        camera->setComputeNearFarMode(osg::CullSettings::DO_NOT_COMPUTE_NEAR_FAR);
        camera->setClearMask(GL_DEPTH_BUFFER_BIT);
        camera->setClearDepth(1.0);
        camera->setViewport(0, 0, size, size);
        camera->setDrawBuffer(GL_NONE);
        camera->setReadBuffer(GL_NONE);
        camera->attach(osg::Camera::DEPTH_BUFFER, _texture.get(), 0, unsigned(_cameras.size()));
        camera->getOrCreateStateSet()->setAttribute(new osg::ColorMask(false, false, false, false),
                                                    osg::StateAttribute::ON | osg::StateAttribute::OVERRIDE);
        osg::ref_ptr<DrawSceneChildren> draw = new DrawSceneChildren;
        camera->setCullCallback(draw.get());
        camera->setName("volren geometry shadow map " + std::to_string(_cameras.size()));
        _cameras.push_back(camera);
    }
    for (std::size_t i = 0; i < n; ++i) {
        osg::Matrixd view, projection;
        if (!lightFrustum(lights[i], receivers, casters, view, projection)) {
            OSG_INFO << "volren: light " << i << " is inside the shadowed volumes' box; opaque geometry does not "
                     << "shadow them from it" << std::endl;
            continue;
        }
        _matrices[i] = view * projection * osg::Matrixd::scale(0.5, 0.5, 0.5) * osg::Matrixd::translate(0.5, 0.5, 0.5);
        if (_drawnFrom[i] == _matrices[i]) continue;  // the layer holds this map
        osg::Camera& camera = *_cameras[i];
        dynamic_cast<DrawSceneChildren&>(*camera.getCullCallback()).scene = &scene;
        camera.setViewMatrix(view);
        camera.setProjectionMatrix(projection);
        camera.accept(cv);
        _drawnFrom[i] = _matrices[i];
        ++_draws;
    }
}

}  // namespace volren
