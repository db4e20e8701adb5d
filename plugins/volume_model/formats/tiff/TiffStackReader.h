#pragma once
#include <volume_model/Volume.h>

#include <osgDB/Options>

#include <string>
#include <vector>

namespace volren::tiff {

/// Reads the pages of `files` (one multi-page TIFF, or numbered 2D slices in order) as one
/// volume: ImageJ hyperstack or OME-XML metadata of a single file give channels, frames and
/// spacing; samples per pixel > 1 (RGB) become channels. Progress goes to the LoadProgress in
/// `options`. `name` is used in messages. Throws std::runtime_error("file: reason").
osg::ref_ptr<Volume> readTiffStack(const std::vector<std::string>& files, const std::string& name,
                                   const osgDB::Options* options);

}  // namespace volren::tiff
