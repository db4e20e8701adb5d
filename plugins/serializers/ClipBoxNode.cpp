// volren::ClipBoxNode: the kept box, min x y z then max x y z.
#include "StreamFields.h"

#include <volume_model/ClipBoxNode.h>

#include <osgDB/ObjectWrapper>

namespace {

using namespace volren::serializers;
using volren::ClipBoxNode;

bool checkBox(const ClipBoxNode&) { return true; }

bool writeBox(osgDB::OutputStream& os, const ClipBoxNode& node)
{
    for (int i = 0; i < 3; ++i) writeDouble(os, node.box._min[i]);
    for (int i = 0; i < 3; ++i) writeDouble(os, node.box._max[i]);
    os << std::endl;
    return true;
}

bool readBox(osgDB::InputStream& is, ClipBoxNode& node)
{
    osg::Vec3d lo, hi;
    for (int i = 0; i < 3; ++i)
        if (!readDouble(is, lo[i], "volren::ClipBoxNode Box")) return false;
    for (int i = 0; i < 3; ++i)
        if (!readDouble(is, hi[i], "volren::ClipBoxNode Box")) return false;
    node.box.set(lo, hi);  // min > max is allowed: an empty box keeps nothing
    return true;
}

}  // namespace

REGISTER_OBJECT_WRAPPER(volren_ClipBoxNode, new volren::ClipBoxNode, volren::ClipBoxNode,
                        "osg::Object osg::Node volren::ClipNode volren::ClipBoxNode")
{
    ADD_USER_SERIALIZER(Box);
}
