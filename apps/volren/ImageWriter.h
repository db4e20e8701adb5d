#pragma once
#include <osg/Image>
#include <string>

namespace volren::app {

/// Writes a read-back RGBA float image (row 0 at the bottom) through OpenImageIO: float RGBA
/// for .exr, 8-bit RGB (rounded, clamped) for everything else. Throws std::runtime_error.
void writeImage(const osg::Image& image, const std::string& path);

}  // namespace volren::app
