#include <volume_model/OpaqueGeometry.h>

namespace volren {

bool drawnAfterOpaque(const osg::StateSet* ss)
{
    return ss && (ss->getRenderingHint() == osg::StateSet::TRANSPARENT_BIN ||
                  (ss->getRenderBinMode() != osg::StateSet::INHERIT_RENDERBIN_DETAILS && ss->getBinNumber() > 0));
}

}  // namespace volren
