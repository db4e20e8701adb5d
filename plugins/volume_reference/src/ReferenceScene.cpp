#include <volume_reference/ReferenceScene.h>

#include <osg/LightSource>
#include <osg/NodeVisitor>
#include <osg/Transform>

namespace volren {

ReferenceScene ReferenceScene::collect(const osg::Node& root)
{
    struct Collector : osg::NodeVisitor
    {
        Collector() : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN) {}
        ReferenceScene scene;
        void apply(osg::Node& node) override
        {
            const osg::Matrixd toWorld = osg::computeLocalToWorld(getNodePath());
            if (auto* v = dynamic_cast<VolumeNode*>(&node)) {
                if (v->getVolume() && v->getTransferFunction() && v->getVolume()->voxelCount() > 0)
                    scene.volumes.push_back({v, toWorld});
            } else if (auto* c = dynamic_cast<ClipNode*>(&node)) {
                scene.clips.push_back({c, toWorld});
            } else if (auto* l = dynamic_cast<osg::LightSource*>(&node); l && l->getLight()) {
                scene.lights.push_back({l, l->getReferenceFrame() == osg::LightSource::ABSOLUTE_RF ? osg::Matrixd() : toWorld});
            }
            traverse(node);
        }
    } collector;
    const_cast<osg::Node&>(root).accept(collector);  // the visitor reads only
    return collector.scene;
}

}  // namespace volren
