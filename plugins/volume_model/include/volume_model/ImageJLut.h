#pragma once
#include <volume_model/TransferFunction.h>

#include <osg/ref_ptr>
#include <string>

namespace volren {

/// Reads an ImageJ / Fiji lookup table (`.lut`; docs/transfer-functions.md) in any of ImageJ's
/// forms: 768 bytes raw (256 reds, 256 greens, 256 blues); NIH Image's binary form, a 32-byte
/// header starting "ICOL" and then N reds, greens and blues (800 bytes for 256 colours; fewer
/// colours spread over the table as ImageJ does); or text, 256 rows of `r g b` or `index r g b`
/// (whitespace or comma separated, an optional heading line first, the index column ignored).
/// Components are 0..255.
///
/// A LUT has neither data values nor opacity. The result has one control point per entry at
/// value 0..255 (an explicit domain [0, 255]: TransferFunction::remap stretches it over a volume's
/// range, as ImageJ stretches a LUT between its display minimum and maximum) and opacity rising
/// linearly with the entry, 0 at entry 0 to 1 at entry 255
/// (the low end of the range see-through, as in fluorescence volume renderers).
/// Throws std::runtime_error naming the file (and "file:line" in text) and the reason.
osg::ref_ptr<TransferFunction> readImageJLut(const std::string& path);

}  // namespace volren
