#include <volume_model/OsgTransferFunction.h>

namespace volren {

osg::ref_ptr<TransferFunction> fromOsgTransferFunction(const osg::TransferFunction1D& osgTf)
{
    osg::ref_ptr<TransferFunction> tf = new TransferFunction;
    tf->setName(osgTf.getName());
    for (const auto& [value, rgba] : osgTf.getColorMap()) tf->setPoint(value, rgba);
    return tf;
}

osg::ref_ptr<osg::TransferFunction1D> toOsgTransferFunction(const TransferFunction& tf)
{
    osg::TransferFunction1D::ColorMap colours;
    for (const auto& [value, rgba] : tf.points()) colours[float(value)] = rgba;
    osg::ref_ptr<osg::TransferFunction1D> osgTf = new osg::TransferFunction1D;
    osgTf->setName(tf.getName());
    osgTf->assign(colours);
    return osgTf;
}

}  // namespace volren
