#include <volume_reference/ReferenceScene.h>

#include <volume_model/OpaqueGeometry.h>

#include <osg/Notify>
#include <osg/KdTree>
#include <osg/LightSource>
#include <osg/NodeVisitor>
#include <osg/Transform>
#include <osg/TriangleFunctor>
#include <osgUtil/IntersectionVisitor>
#include <osgUtil/LineSegmentIntersector>

namespace volren {

namespace {

/// Appends a drawable's triangles, placed by `toWorld`, to `vertices`.
struct TriangleCollector
{
    osg::Vec3Array* vertices = nullptr;
    osg::Matrixd toWorld;
    void operator()(const osg::Vec3& a, const osg::Vec3& b, const osg::Vec3& c)
    {
        for (const osg::Vec3* v : {&a, &b, &c}) vertices->push_back(osg::Vec3d(*v) * toWorld);
    }
};

}  // namespace

ReferenceScene ReferenceScene::collect(const osg::Node& root)
{
    struct Collector : osg::NodeVisitor
    {
        Collector() : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN) {}
        ReferenceScene scene;
        osg::ref_ptr<osg::Vec3Array> triangles = new osg::Vec3Array;
        int notOpaque = 0;  ///< depth below state drawn after the opaque bin, or a volume or clip node

        void apply(osg::Drawable& drawable) override
        {
            if (notOpaque > 0 || drawnAfterOpaque(drawable.getStateSet())) return;
            osg::TriangleFunctor<TriangleCollector> functor;
            functor.vertices = triangles.get();
            functor.toWorld = osg::computeLocalToWorld(getNodePath());
            drawable.accept(functor);
        }
        void apply(osg::Node& node) override
        {
            const osg::Matrixd toWorld = osg::computeLocalToWorld(getNodePath());
            bool skip = drawnAfterOpaque(node.getStateSet());
            if (auto* v = dynamic_cast<VolumeNode*>(&node)) {
                try {
                    for (VolumeNode* drawn : v->drawnNodes())  // itself, or its visible channels
                        if (drawn->getVolume() && drawn->getTransferFunction() && drawn->getVolume()->voxelCount() > 0)
                            scene.volumes.push_back({drawn, toWorld});
                } catch (const std::exception& e) {  // copying its blocks out (memory): left out, as the renderer does
                    OSG_WARN << "volren reference: volume '" << v->getName() << "' left out: " << e.what() << std::endl;
                }
                skip = true;
            } else if (auto* c = dynamic_cast<ClipNode*>(&node)) {
                scene.clips.push_back({c, toWorld});
                skip = true;
            } else if (auto* l = dynamic_cast<osg::LightSource*>(&node); l && l->getLight()) {
                scene.lights.push_back({l, l->getReferenceFrame() == osg::LightSource::ABSOLUTE_RF ? osg::Matrixd() : toWorld});
            }
            notOpaque += skip;
            traverse(node);
            notOpaque -= skip;
        }
    } collector;
    const_cast<osg::Node&>(root).accept(collector);  // the visitor reads only
    if (!collector.triangles->empty()) {
        osg::ref_ptr<osg::Geometry> geometry = new osg::Geometry;
        geometry->setVertexArray(collector.triangles.get());
        geometry->addPrimitiveSet(new osg::DrawArrays(GL_TRIANGLES, 0, GLsizei(collector.triangles->size())));
        osg::ref_ptr<osg::KdTreeBuilder> builder = new osg::KdTreeBuilder;
        geometry->accept(*builder);
        collector.scene.occluders = geometry;
    }
    return collector.scene;
}

bool ReferenceScene::occluded(const osg::Vec3d& from, const osg::Vec3d& to) const
{
    if (!occluders) return false;
    osg::ref_ptr<osgUtil::LineSegmentIntersector> segment = new osgUtil::LineSegmentIntersector(from, to);
    segment->setIntersectionLimit(osgUtil::Intersector::LIMIT_ONE);
    osgUtil::IntersectionVisitor visitor(segment.get());
    visitor.setUseKdTreeWhenAvailable(true);
    const_cast<osg::Geometry&>(*occluders).accept(visitor);  // the visitor reads only
    return segment->containsIntersections();
}

const std::map<std::string, std::vector<std::string>>& ReferenceScene::models()
{
    static const std::map<std::string, std::vector<std::string>> names = {
        {"Shading", {"unlit", "lit", "lit above threshold", "lit on surfaces"}},
        {"Illumination",
         {"no light", "lambert diffuse", "diffuse + blinn-phong highlight", "diffuse + cook-torrance ggx highlight",
          "henyey-greenstein phase"}},
        {"Shadowing", {"unshadowed", ReferenceScene::exactShadows, ReferenceScene::exactShadowsAndOcclusion}},
        {"Weighting", {"unweighted", "axis curves"}},
        // What the integrator itself does for every volume: an implementation declaring one of
        // these computes it (or approximates it within its bound); one that computes anything
        // else declares Fidelity::None, and no reference compares it.
        {"RaySetup", {"the volume box from the near plane"}},
        {"VolumeStorage", {"voxel values"}},
        {"Reconstruction", {"trilinear field"}},
        {"Classification", {"post-classified transfer function"}},
        {"GradientInput", {"no gradient", "scalar field"}},
        {"Gradient", {"no gradient", "central differences"}},  // no gradient: zero, normals face the viewer
        {"ClipPosition", {"clip shape"}},
        {"ClipRay", {"clip shape", "opaque geometry's depth"}},
        {"Acceleration", {"every sample"}},
        {"Jitter", {"no jitter"}},
        {"RayTraversal", {"emission-absorption"}}};
    return names;
}

}  // namespace volren
