#include "OmeZarrVolume.h"

#include <volume_model/LoadProgress.h>
#include <volume_model/OmeZarrImage.h>

#include <osg/Matrixd>
#include <osg/Notify>

#include <climits>
#include <stdexcept>

namespace volren::omezarr {

namespace {

std::string sizeText(const std::array<std::uint64_t, 3>& s, std::uint64_t blocks)
{
    return std::to_string(s[0]) + "x" + std::to_string(s[1]) + "x" + std::to_string(s[2]) + " voxels" +
           (blocks > 1 ? " x " + std::to_string(blocks) + " channels and time points" : std::string());
}

/// Whether level `i` fits a Volume: dims within int, voxel count within Volume::maxVoxels.
bool fits(const OmeZarrImage& image, std::size_t i, std::uint64_t blocks)
{
    const std::array<std::uint64_t, 3> s = image.size(i);
    std::uint64_t n = blocks;
    for (std::uint64_t v : s) {
        if (v > std::uint64_t(INT_MAX) || v > Volume::maxVoxels / n) return false;
        n *= v;
    }
    return n <= Volume::maxVoxels;
}

}  // namespace

osg::ref_ptr<Volume> readOmeZarrVolume(const std::string& path, std::size_t level, const osgDB::Options* options)
{
    const OmeZarrImage image(path);
    const std::size_t levels = image.levelCount();
    if (level >= levels)
        throw std::runtime_error(path + ": option level=" + std::to_string(level) + ", but the image has level" +
                                 (levels == 1 ? " 0 only" : "s 0 to " + std::to_string(levels - 1)));
    const std::uint64_t frames = image.frames(), channels = image.channels(), blocks = frames * channels;
    const std::array<std::uint64_t, 3> size = image.size(level);
    if (!fits(image, level, blocks) || frames > std::uint64_t(INT_MAX) || channels > std::uint64_t(INT_MAX)) {
        std::string hint = "no level of this image is small enough";
        for (std::size_t i = level + 1; i < levels; ++i)
            if (fits(image, i, blocks)) {
                hint = "read a coarser level with the option level=" + std::to_string(i) + " (" + sizeText(image.size(i), blocks) + ")";
                break;
            }
        throw std::runtime_error(path + ": level " + std::to_string(level) + " is " + sizeText(size, blocks) +
                                 ", over volren's limit of 2^34 voxels; " + hint);
    }

    const ZarrArray& array = image.level(level);
    const osg::Vec3i dims(static_cast<int>(size[0]), static_cast<int>(size[1]), static_cast<int>(size[2]));
    osg::ref_ptr<Volume> volume = new Volume;
    try {
        volume->allocate(array.voxelType(), dims, int(channels), int(frames));
    } catch (const std::bad_alloc&) {
        throw std::runtime_error(path + ": not enough memory for level " + std::to_string(level) + " (" + sizeText(size, blocks) + ")");
    }
    // OME-Zarr orders the axes [t] [c] z y x, so the whole level in C order is the Volume's
    // layout: block (c, t) at t * channels + c, x fastest.
    ZarrBox box;
    box.begin.assign(array.dimensions(), 0);
    box.end = array.metadata().shape;
    const LoadProgress* progress = loadProgressOf(options);
    array.readRegion(box, volume->data(), progress);
    if (array.missingChunks() > 0)
        OSG_NOTICE << path << ": " << array.missingChunks() << " chunk files of level " << level
                   << " are missing; their voxels are the fill value " << array.metadata().fillValue << std::endl;

    const std::array<double, 3> spacing = image.spacing(level);
    const std::array<double, 3> origin = image.origin(level);
    volume->setSpacing(osg::Vec3d(spacing[0], spacing[1], spacing[2]));
    const OmeZarrAttributes& a = image.attributes();
    volume->setRescale(a.rescaleSlope, a.rescaleIntercept);
    volume->setUserValue("voxelToWorld", osg::Matrixd::scale(spacing[0], spacing[1], spacing[2]) *
                                             osg::Matrixd::translate(origin[0], origin[1], origin[2]));
    volume->setUserValue("voxelToWorldSource", std::string("ome-zarr"));
    if (!image.spaceUnit().empty()) volume->setUserValue(spacingUnitKey, image.spaceUnit());
    if (image.timeAxis() >= 0) {
        volume->setUserValue(timeStepKey, image.timeStep(level));
        if (!image.timeUnit().empty()) volume->setUserValue(timeUnitKey, image.timeUnit());
    }
    volume->setUserValue(levelCountKey, int(levels));
    volume->sourceFile = path;
    volume->dirty();
    OSG_INFO << path << ": OME-Zarr " << a.version << ", level " << level << " of " << levels << ", " << sizeText(size, blocks) << " "
             << array.metadata().dtype.str() << ", spacing " << spacing[0] << " " << spacing[1] << " " << spacing[2] << " "
             << image.spaceUnit() << std::endl;
    return volume;
}

}  // namespace volren::omezarr
