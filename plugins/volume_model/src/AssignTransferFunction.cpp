#include <volume_model/AssignTransferFunction.h>
#include <volume_model/TransferFunctionFile.h>

namespace volren {

void assignTransferFunctionFile(const std::vector<VolumeNode*>& nodes, const std::string& file, bool keepRange)
{
    osg::ref_ptr<TransferFunction> tf = readTransferFunctionFile(file);
    const bool stretch = transferFunctionFitsAnyRange(file) && !keepRange;
    for (VolumeNode* node : nodes) {
        if (stretch && node->getVolume()) {
            osg::ref_ptr<TransferFunction> fitted = new TransferFunction(*tf);
            const auto [lo, hi] = node->getVolume()->valueRange();
            fitted->remap(lo, hi > lo ? hi : lo + 1.0);
            node->setTransferFunction(fitted.get());
        } else {
            node->setTransferFunction(tf.get());
        }
        // Every channel then shows through it (their own transfer functions are dropped).
        for (ChannelDisplay& channel : node->channels) channel.transferFunction = nullptr;
    }
}

}  // namespace volren
