// volren::ClipEllipsoidNode: centre and semi-axes.
#include "StreamFields.h"

#include <volume_model/ClipEllipsoidNode.h>

#include <osgDB/ObjectWrapper>

namespace {

using namespace volren::serializers;
using volren::ClipEllipsoidNode;

bool writeVec3(osgDB::OutputStream& os, const osg::Vec3d& v)
{
    for (int i = 0; i < 3; ++i) writeDouble(os, v[i]);
    os << std::endl;
    return true;
}

bool readVec3(osgDB::InputStream& is, osg::Vec3d& v, const std::string& field)
{
    for (int i = 0; i < 3; ++i)
        if (!readDouble(is, v[i], field)) return false;
    return true;
}

bool checkCenter(const ClipEllipsoidNode&) { return true; }
bool writeCenter(osgDB::OutputStream& os, const ClipEllipsoidNode& node) { return writeVec3(os, node.center); }
bool readCenter(osgDB::InputStream& is, ClipEllipsoidNode& node)
{
    return readVec3(is, node.center, "volren::ClipEllipsoidNode Center");
}

bool checkRadii(const ClipEllipsoidNode&) { return true; }
bool writeRadii(osgDB::OutputStream& os, const ClipEllipsoidNode& node) { return writeVec3(os, node.radii); }
bool readRadii(osgDB::InputStream& is, ClipEllipsoidNode& node)
{
    osg::Vec3d radii;
    if (!readVec3(is, radii, "volren::ClipEllipsoidNode Radii")) return false;
    if (!(radii.x() > 0 && radii.y() > 0 && radii.z() > 0))
        return fail(is, "volren::ClipEllipsoidNode Radii: semi-axes must be positive"), false;
    node.radii = radii;
    return true;
}

}  // namespace

REGISTER_OBJECT_WRAPPER(volren_ClipEllipsoidNode, new volren::ClipEllipsoidNode, volren::ClipEllipsoidNode,
                        "osg::Object osg::Node volren::ClipNode volren::ClipEllipsoidNode")
{
    ADD_USER_SERIALIZER(Center);
    ADD_USER_SERIALIZER(Radii);
}
