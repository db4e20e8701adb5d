#pragma once
#include <volume_model/TransferFunction.h>

#include <osg/ref_ptr>
#include <string>

namespace volren {

/// Reads a ParaView colour-map preset (the JSON that ParaView's "Export Presets" writes: one
/// preset object or a list of them). `name` picks a preset by its "Name"; empty takes the first.
/// "RGBPoints" [x, r, g, b, ...] give the colours, "Points" [x, opacity, midpoint, sharpness, ...]
/// the opacity (a linear 0 -> 1 ramp over the colour range when absent, as ParaView starts).
/// Colours are interpolated in RGB whatever the preset's "ColorSpace" (between its points only).
/// Point values are kept as they are; ParaView rescales presets to the data range on apply,
/// which TransferFunction::remap does. Throws std::runtime_error naming the file and the reason
/// (not JSON, no such preset, categorical presets, shaped opacity segments, bad numbers).
osg::ref_ptr<TransferFunction> readParaViewPreset(const std::string& path, const std::string& name = "");

}  // namespace volren
