// volren::ClipNode (abstract): `Invert`, shared by every clip shape.
#include "StreamFields.h"

#include <volume_model/ClipNode.h>

#include <osgDB/ObjectWrapper>

namespace {

using namespace volren::serializers;
using volren::ClipNode;

bool checkInvert(const ClipNode& node) { return node.invert; }

bool writeInvert(osgDB::OutputStream& os, const ClipNode& node)
{
    writeBool(os, node.invert);
    os << std::endl;
    return true;
}

bool readInvert(osgDB::InputStream& is, ClipNode& node)
{
    return readBool(is, node.invert, "volren::ClipNode Invert");
}

}  // namespace

REGISTER_OBJECT_WRAPPER(volren_ClipNode, nullptr, volren::ClipNode, "osg::Object osg::Node volren::ClipNode")
{
    ADD_USER_SERIALIZER(Invert);
}
