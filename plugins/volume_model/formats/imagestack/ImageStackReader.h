#pragma once
#include <volume_model/Volume.h>

#include <osgDB/Options>

#include <string>
#include <vector>

namespace volren::imagestack {

/// Image file extensions (lower case) taken from a directory.
const std::vector<std::string>& imageExtensions();

/// Stacks the 2D images `files` (in this order, z = index) with OpenImageIO. All images must
/// have the same size, channel count and pixel type; every channel becomes a volume channel;
/// 8/16-bit integers keep their type, other types become float32. Spacing comes from the
/// `spacing=x,y,z` option (default 1). Progress goes to the LoadProgress in `options`.
/// Throws std::runtime_error("file: reason"); `name` names the stack.
osg::ref_ptr<Volume> readImageStack(const std::vector<std::string>& files, const std::string& name,
                                    const osgDB::Options* options);

}  // namespace volren::imagestack
