#include <volume_model/AutoTransferFunction.h>

#include <algorithm>

namespace volren {

osg::ref_ptr<TransferFunction> makeTransferFunctionFromHistogram(const Volume& volume)
{
    const Histogram h = volume.histogram(256);
    const auto [lo, hi] = volume.valueRange();
    osg::ref_ptr<TransferFunction> tf = new TransferFunction;
    tf->setName("auto");
    if (!(hi > lo)) {  // constant volume: a faint grey so the box is visible
        tf->setPoint(lo, osg::Vec4(0.8f, 0.8f, 0.8f, 0.02f));
        tf->setDomain(lo - 0.5, lo + 0.5);
        return tf;
    }
    double start = h.otsuThreshold();
    double top = h.percentile(0.995);
    if (!(top > start)) top = hi;
    if (!(top > start)) start = lo;
    const double span = top - start;
    tf->setPoint(lo, osg::Vec4(0.0f, 0.0f, 0.0f, 0.0f));
    tf->setPoint(start, osg::Vec4(0.55f, 0.20f, 0.10f, 0.0f));
    tf->setPoint(start + 0.35 * span, osg::Vec4(0.85f, 0.55f, 0.35f, 0.04f));
    tf->setPoint(start + 0.7 * span, osg::Vec4(1.0f, 0.85f, 0.70f, 0.12f));
    tf->setPoint(std::max(top, start + 1e-9 * std::max(1.0, std::abs(start))), osg::Vec4(1.0f, 1.0f, 1.0f, 0.3f));
    tf->setDomain(lo, hi);
    return tf;
}

}  // namespace volren
