#pragma once
#include <volume_model/TransferFunction.h>
#include <volume_model/Volume.h>

#include <osg/ref_ptr>

namespace volren {

/// A transfer function derived from the volume's histogram: transparent below the Otsu
/// background threshold, then a warm ramp to white with rising opacity up to the 99.5th
/// percentile. Good first view of CT, MRI and microscopy data.
osg::ref_ptr<TransferFunction> makeTransferFunctionFromHistogram(const Volume& volume);

}  // namespace volren
