// volren::ClipPlaneNode: the plane a b c d (kept where a*x + b*y + c*z + d >= 0).
#include "StreamFields.h"

#include <volume_model/ClipPlaneNode.h>

#include <osgDB/ObjectWrapper>

namespace {

using namespace volren::serializers;
using volren::ClipPlaneNode;

bool checkPlane(const ClipPlaneNode&) { return true; }

bool writePlane(osgDB::OutputStream& os, const ClipPlaneNode& node)
{
    for (int i = 0; i < 4; ++i) writeDouble(os, node.plane[i]);
    os << std::endl;
    return true;
}

bool readPlane(osgDB::InputStream& is, ClipPlaneNode& node)
{
    double v[4];
    for (double& c : v)
        if (!readDouble(is, c, "volren::ClipPlaneNode Plane")) return false;
    node.plane.set(v[0], v[1], v[2], v[3]);
    return true;
}

}  // namespace

REGISTER_OBJECT_WRAPPER(volren_ClipPlaneNode, new volren::ClipPlaneNode, volren::ClipPlaneNode,
                        "osg::Object osg::Node volren::ClipNode volren::ClipPlaneNode")
{
    ADD_USER_SERIALIZER(Plane);
}
