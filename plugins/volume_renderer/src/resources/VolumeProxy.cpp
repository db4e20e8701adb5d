#include "VolumeProxy.h"

#include <volume_renderer/MatrixUniforms.h>

#include <osg/BlendFunc>
#include <osg/CullFace>
#include <osg/Depth>
#include <osg/Geode>

namespace volren {

namespace {

osg::ref_ptr<osg::Geometry> makeBoxGeometry(const osg::Vec3d& size)
{
    const osg::Vec3 h = osg::Vec3(size) * 0.5f;
    osg::ref_ptr<osg::Vec3Array> corners = new osg::Vec3Array;
    for (int i = 0; i < 8; ++i)
        corners->push_back(osg::Vec3((i & 1) ? h.x() : -h.x(), (i & 2) ? h.y() : -h.y(), (i & 4) ? h.z() : -h.z()));
    // Two counter-clockwise (outward) triangles per face.
    static const GLushort faces[] = {0, 2, 3, 0, 3, 1,  4, 5, 7, 4, 7, 6,  0, 1, 5, 0, 5, 4,
                                     2, 6, 7, 2, 7, 3,  0, 4, 6, 0, 6, 2,  1, 3, 7, 1, 7, 5};
    osg::ref_ptr<osg::Geometry> geometry = new osg::Geometry;
    geometry->setName("volren volume proxy");
    geometry->setUseDisplayList(false);
    geometry->setUseVertexBufferObjects(false);  // buffer objects and a VAO only in core profiles
    geometry->setVertexArray(corners.get());
    geometry->addPrimitiveSet(new osg::DrawElementsUShort(GL_TRIANGLES, 36, faces));
    geometry->setDrawCallback(new MatrixUniforms);  // for viewers whose State sets no osg_ matrices
    return geometry;
}

}  // namespace

osg::StateSet& VolumeProxy::update(const osg::Vec3d& size, std::shared_ptr<const ComposedProgram> composed)
{
    if (!geometry || boxSize != size) {
        boxSize = size;
        geometry = makeBoxGeometry(boxSize);
        osg::ref_ptr<osg::Geode> geode = new osg::Geode;
        geode->addDrawable(geometry.get());
        transform->removeChildren(0, transform->getNumChildren());
        transform->addChild(geode.get());
        geometry->getOrCreateStateSet();
        key.clear();
    }
    osg::StateSet& ss = *geometry->getStateSet();
    if (key != composed->key) {  // new composition: state from scratch
        ss.clear();
        ss.setAttributeAndModes(new osg::CullFace(osg::CullFace::FRONT), osg::StateAttribute::ON);
        ss.setAttributeAndModes(new osg::BlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA), osg::StateAttribute::ON);
        ss.setRenderBinDetails(10, "DepthSortedBin");
        if (composed->writesDepth) {  // an opaque surface: depth-tested and written like geometry
            ss.setAttributeAndModes(new osg::Depth(osg::Depth::LESS, 0.0, 1.0, true), osg::StateAttribute::ON);
        } else {
            ss.setMode(GL_DEPTH_TEST, osg::StateAttribute::OFF);
        }
        ss.setAttributeAndModes(composed->program.get(), osg::StateAttribute::ON);
        key = composed->key;
    }
    program = std::move(composed);
    return ss;
}

void VolumeProxy::useVertexArrayObject(bool core)
{
    if (geometry->getUseVertexArrayObject() == core) return;
    geometry->setUseVertexBufferObjects(core);
    geometry->setUseVertexArrayObject(core);
}

}  // namespace volren
