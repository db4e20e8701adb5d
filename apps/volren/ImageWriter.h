#pragma once
#include <osg/Image>

#include <string>
#include <vector>

namespace volren::app {

/// Writes a read-back RGBA float image (row 0 at the bottom) through OpenImageIO: float RGBA
/// for .exr, 8-bit RGB (rounded, clamped) for everything else. Throws std::runtime_error.
void writeImage(const osg::Image& image, const std::string& path);

/// Writes read-back frames as one animated GIF (8-bit RGB, looping, `fps` frames per second)
/// through OpenImageIO's GIF writer. Throws std::runtime_error.
void writeAnimatedGif(const std::vector<osg::ref_ptr<osg::Image>>& frames, const std::string& path, int fps);

/// `path` with a 1-based frame number before its extension: out.png, 3 -> out_0003.png.
std::string numberedPath(const std::string& path, int frame);

}  // namespace volren::app
