#pragma once
#include <volume_model/TransferFunction.h>

#include <osg/ref_ptr>
#include <string>

namespace volren {

/// Reads OSG's `.tf` text format: lines `value r g b a [comment]`, `#` comments, and an optional
/// `colour-scale S` (components are divided by S, 255 by default). Values are data values.
/// Unlike the stock osgdb_tf reader it rejects malformed lines; throws std::runtime_error
/// with "file:line: reason".
osg::ref_ptr<TransferFunction> readTransferFunctionFile(const std::string& path);

/// Writes `tf` in the `.tf` format with `colour-scale 1` (exact floats); throws std::runtime_error.
void writeTransferFunctionFile(const TransferFunction& tf, const std::string& path);

}  // namespace volren
