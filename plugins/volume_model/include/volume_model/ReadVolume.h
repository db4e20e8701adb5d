#pragma once
#include <volume_model/Volume.h>

#include <osgDB/Options>
#include <string>

namespace volren {

/// Reads a volume file through the volren osgDB plugins (found by extension; `x.nii.gz` is
/// handled by the `nii` plugin directly, so errors name the file). Throws std::runtime_error
/// with a message that names the file and the reason.
osg::ref_ptr<Volume> readVolumeFile(const std::string& path, const osgDB::Options* options = nullptr);

/// Extension that selects the reader: lower case, with a trailing `.gz` looked through.
std::string volumeFileExtension(const std::string& path);

/// Whether a volren volume reader is registered for `path`'s extension, or `path` is a
/// directory (of TIFF, 2D image or DICOM slices, or an OME-Zarr image / zarr array).
bool isVolumeFile(const std::string& path);

/// Adds the folder holding the volren osgDB plugins (next to this library) to OSG's
/// library path, once, and volren's data folders to its data path (registerDataPath);
/// called by readVolumeFile and by programs before reading scenes.
void registerPluginPath();

/// Folder of shared volren resources (shaders/, data/): $VOLREN_SHARE_DIR, else the
/// share/volren folder of the tree (build or install) this library lies in.
std::string shareDirectory();

}  // namespace volren
