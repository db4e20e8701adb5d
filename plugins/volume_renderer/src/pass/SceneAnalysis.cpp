#include "SceneAnalysis.h"

#include <volume_model/ClipNode.h>
#include <volume_model/OpaqueGeometry.h>

#include <osg/Drawable>
#include <osg/LightSource>
#include <osg/Transform>
#include <osg/Notify>
#include <osg/NodeVisitor>

#include <array>

namespace volren {

namespace {

/// Finds volumes, lights and clip shapes below a VolumeScene, with matrices relative to it.
class SceneCollector : public osg::NodeVisitor
{
public:
    explicit SceneCollector(unsigned int mask) : osg::NodeVisitor(TRAVERSE_ACTIVE_CHILDREN) { setTraversalMask(mask); }
    std::vector<std::pair<VolumeNode*, osg::Matrix>> volumes;
    std::vector<std::pair<const osg::LightSource*, osg::Matrix>> lights;
    std::vector<std::pair<const ClipNode*, osg::Matrix>> clips;
    bool opaqueGeometry = false;  ///< some drawable outside the transparent bins

    void apply(osg::Drawable& drawable) override
    {
        if (_transparent == 0 && !drawnAfterOpaque(drawable.getStateSet())) opaqueGeometry = true;
    }
    void apply(osg::Node& node) override
    {
        const bool transparent = drawnAfterOpaque(node.getStateSet());
        _transparent += transparent;
        visit(node);
        _transparent -= transparent;
    }
    void apply(osg::LightSource& light) override
    {
        if (light.getLight()) lights.emplace_back(&light, _matrix);
        apply(static_cast<osg::Node&>(light));
    }
    void apply(osg::Transform& transform) override
    {
        const osg::Matrix saved = _matrix;
        transform.computeLocalToWorldMatrix(_matrix, this);
        apply(static_cast<osg::Node&>(transform));
        _matrix = saved;
    }

private:
    void visit(osg::Node& node)
    {
        if (auto* v = dynamic_cast<VolumeNode*>(&node)) {
            try {
                for (VolumeNode* drawn : v->drawnNodes())  // itself, or its visible channels (one ray)
                    if (drawn->getVolume() && drawn->getTransferFunction() && drawn->getVolume()->voxelCount() > 0)
                        volumes.emplace_back(drawn, _matrix);
            } catch (const std::exception& e) {  // copying its blocks out (memory): not drawn
                OSG_WARN << "volren: cannot draw volume '" << v->getName() << "': " << e.what() << std::endl;
            }
            return;
        }
        if (auto* c = dynamic_cast<ClipNode*>(&node)) {
            clips.emplace_back(c, _matrix);
            return;
        }
        traverse(node);
    }
    osg::Matrix _matrix;
    int _transparent = 0;
};

LightInfo lightInfo(const osg::LightSource& source, const osg::Matrixd& toLocal)
{
    const osg::Light* light = source.getLight();
    const osg::Vec4d p = light->getPosition();
    LightInfo info;
    if (p.w() == 0.0) {
        osg::Vec3d d = osg::Matrixd::transform3x3(osg::Vec3d(p.x(), p.y(), p.z()), toLocal);
        d.normalize();
        info.position = osg::Vec4d(d, 0.0);
    } else {
        info.position = osg::Vec4d(osg::Vec3d(p.x(), p.y(), p.z()) / p.w() * toLocal, 1.0);
    }
    const osg::Vec4 c = light->getDiffuse();
    info.colour = osg::Vec3d(c.r(), c.g(), c.b());
    return info;
}

/// What the scene offers `volumeMatrix`'s volume (all matrices relative to the VolumeScene).
SceneOffer offerFor(const VolumeNode& node, const osg::Matrix& volumeMatrix, const SceneCollector& scene,
                    const osg::Matrix& sceneModelView)
{
    SceneOffer offer;
    offer.opaqueGeometry = scene.opaqueGeometry;
    const osg::Matrixd sceneToLocal = osg::Matrixd::inverse(volumeMatrix);
    const osg::Matrixd eyeToLocal = osg::Matrixd::inverse(volumeMatrix * sceneModelView);
    for (const auto& [source, matrix] : scene.lights)
        offer.lights.push_back(lightInfo(
            *source, source->getReferenceFrame() == osg::LightSource::ABSOLUTE_RF ? eyeToLocal : matrix * sceneToLocal));
    const osg::Matrixd texToScene = textureToLocal(*node.getVolume()) * volumeMatrix;
    for (const auto& [clip, matrix] : scene.clips) {
        const osg::Matrixd texToShape = texToScene * osg::Matrixd::inverse(matrix);
        std::array<osg::Vec3d, 8> corners;
        for (int i = 0; i < 8; ++i) corners[i] = osg::Vec3d(i & 1, (i >> 1) & 1, (i >> 2) & 1) * texToShape;
        if (!clip->leavesUnchanged(corners)) offer.clips.push_back(ClipInfo{clip, texToShape});
    }
    return offer;
}

}  // namespace

osg::Matrixd textureToLocal(const Volume& volume)
{
    const osg::Vec3d size = volume.worldSize();
    return osg::Matrixd::translate(-0.5, -0.5, -0.5) * osg::Matrixd::scale(size);
}

std::vector<VolumeCandidate> analyseScene(osg::Group& scene, unsigned int mask, const osg::Matrix& modelView,
                                          bool lighting)
{
    SceneCollector collector(mask);
    for (unsigned int i = 0; i < scene.getNumChildren(); ++i) scene.getChild(i)->accept(collector);
    if (collector.lights.size() > CompositionPolicy::maxLights && lighting)
        OSG_WARN << "volren: " << collector.lights.size() << " lights; volumes use the first "
                 << CompositionPolicy::maxLights << std::endl;
    std::vector<VolumeCandidate> out;
    for (auto& [node, matrix] : collector.volumes) {
        VolumeCandidate c{node, matrix, offerFor(*node, matrix, collector, modelView), {}, 0, false, {}};
        for (const auto& [source, lightMatrix] : collector.lights)
            c.sceneLights.push_back(lightInfo(*source, source->getReferenceFrame() == osg::LightSource::ABSOLUTE_RF
                                                           ? osg::Matrixd::inverse(modelView)
                                                           : osg::Matrixd(lightMatrix)));
        const osg::Matrixd texToScene = textureToLocal(*node->getVolume()) * matrix;
        for (int i = 0; i < 8; ++i) c.bound.expandBy(osg::Vec3d(i & 1, (i >> 1) & 1, (i >> 2) & 1) * texToScene);
        out.push_back(std::move(c));
    }
    return out;
}

}  // namespace volren
