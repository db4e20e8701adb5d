// volren::ClipMaskNode: the mask Volume (a nested object, shareable like any Volume) and the
// threshold at which it keeps.
#include "StreamFields.h"

#include <volume_model/ClipMaskNode.h>

#include <osgDB/ObjectWrapper>

namespace {

using namespace volren::serializers;
using volren::ClipMaskNode;

bool checkMask(const ClipMaskNode& node) { return node.mask.valid(); }

bool writeMask(osgDB::OutputStream& os, const ClipMaskNode& node)
{
    writeObjectField(os, node.mask.get());
    return true;
}

bool readMask(osgDB::InputStream& is, ClipMaskNode& node)
{
    return readObjectField(is, node.mask, "volren::ClipMaskNode Mask", "volren::Volume");
}

bool checkThreshold(const ClipMaskNode&) { return true; }

bool writeThreshold(osgDB::OutputStream& os, const ClipMaskNode& node)
{
    writeDouble(os, node.threshold);
    os << std::endl;
    return true;
}

bool readThreshold(osgDB::InputStream& is, ClipMaskNode& node)
{
    return readDouble(is, node.threshold, "volren::ClipMaskNode Threshold");
}

}  // namespace

REGISTER_OBJECT_WRAPPER(volren_ClipMaskNode, new volren::ClipMaskNode, volren::ClipMaskNode,
                        "osg::Object osg::Node volren::ClipNode volren::ClipMaskNode")
{
    ADD_USER_SERIALIZER(Mask);
    ADD_USER_SERIALIZER(Threshold);
}
