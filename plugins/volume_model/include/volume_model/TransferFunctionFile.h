#pragma once
#include <volume_model/TransferFunction.h>

#include <osg/ref_ptr>
#include <string>

namespace volren {

/// Reads a transfer function, by extension: `.json` is a ParaView colour-map preset
/// (readParaViewPreset; `presets.json#Name` picks one preset of a list), `.vp` a 3D Slicer volume
/// property (readSlicerVolumeProperty; a gradient opacity is ignored with a notice), `.lut` an
/// ImageJ / Fiji lookup table (readImageJLut), anything else OSG's `.tf` text format (readTfFile).
/// Throws std::runtime_error naming the file and the reason.
osg::ref_ptr<TransferFunction> readTransferFunctionFile(const std::string& path);

/// Whether `path` names a ParaView preset file (`x.json`, or `x.json#Name` for one preset of it).
bool isParaViewPreset(const std::string& path);

/// Whether the file's points are not data values but a shape to stretch over a volume's value
/// range (TransferFunction::remap): ParaView presets and ImageJ LUTs. False for `.tf` and `.vp`,
/// whose points are data values.
bool transferFunctionFitsAnyRange(const std::string& path);

/// Reads OSG's `.tf` text format (docs/transfer-functions.md): lines `value r g b a [comment]`,
/// `#` comments, an optional `colour-scale S` (components are divided by S, 255 by default), and
/// volren's own comment lines `#volren domain MIN MAX` / `#volren resolution N`. Values are data
/// values. Unlike the stock osgdb_tf reader it rejects malformed lines; throws
/// std::runtime_error with "file:line: reason".
osg::ref_ptr<TransferFunction> readTfFile(const std::string& path);

/// Saves `tf` in the `.tf` format (`colour-scale 1`, numbers that read back exactly, domain and
/// resolution as `#volren` lines the stock reader skips). Writes a temporary file next to `path`
/// and renames it, so a failure never leaves a half-written file; throws std::runtime_error.
void writeTransferFunctionFile(const TransferFunction& tf, const std::string& path);

}  // namespace volren
