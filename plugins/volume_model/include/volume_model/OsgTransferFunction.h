#pragma once
#include <volume_model/TransferFunction.h>

#include <osg/TransferFunction>

namespace volren {

/// The same control points as a volren TransferFunction (what OSG's own `.tf` reader, osgdb_tf,
/// and osgVolume hand out); throws std::invalid_argument for components outside [0,1].
osg::ref_ptr<TransferFunction> fromOsgTransferFunction(const osg::TransferFunction1D& osgTf);

/// The control points as an osg::TransferFunction1D (float values: points closer than a float
/// ulp merge), for OSG's `.tf` writer and osgVolume.
osg::ref_ptr<osg::TransferFunction1D> toOsgTransferFunction(const TransferFunction& tf);

}  // namespace volren
