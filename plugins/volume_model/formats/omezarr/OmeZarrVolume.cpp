#include "OmeZarrVolume.h"

#include <volume_model/LazyOpening.h>
#include <volume_model/LoadProgress.h>
#include <volume_model/OmeZarrImage.h>
#include <volume_model/OmeZarrSource.h>

#include <osg/Matrixd>
#include <osg/Notify>

#include <climits>
#include <cstdint>
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

/// The user values both readers set: placement, units, time step, level count.
void setImageUserValues(Volume& volume, const OmeZarrImage& image, std::size_t level, const osg::Vec3d& spacing, const osg::Vec3d& origin)
{
    volume.setUserValue("voxelToWorld", osg::Matrixd::scale(spacing) * osg::Matrixd::translate(origin));
    volume.setUserValue("voxelToWorldSource", std::string("ome-zarr"));
    if (!image.spaceUnit().empty()) volume.setUserValue(spacingUnitKey, image.spaceUnit());
    if (image.timeAxis() >= 0) {
        volume.setUserValue(timeStepKey, image.timeStep(level));
        if (!image.timeUnit().empty()) volume.setUserValue(timeUnitKey, image.timeUnit());
    }
    volume.setUserValue(levelCountKey, int(image.levelCount()));
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
    setImageUserValues(*volume, image, level, osg::Vec3d(spacing[0], spacing[1], spacing[2]), osg::Vec3d(origin[0], origin[1], origin[2]));
    volume->sourceFile = path;
    // The omero block's colour, window (stored values) and visibility of each channel.
    if (a.channels.size() == channels)
        for (const OmeroChannel& ch : a.channels) {
            ChannelHint hint;
            hint.name = ch.label;
            if (!ch.color.empty()) hint.colours = {osg::Vec3f(ch.red, ch.green, ch.blue)};
            // A window over the channel's whole range (start = min, end = max, as writers put by
            // default) sets nothing: the channel gets its percentile window.
            hint.hasWindow = ch.hasWindow && ch.windowEnd > ch.windowStart &&
                             !(ch.windowStart <= ch.windowMin && ch.windowEnd >= ch.windowMax);
            hint.low = ch.windowStart * a.rescaleSlope + a.rescaleIntercept;
            hint.high = ch.windowEnd * a.rescaleSlope + a.rescaleIntercept;
            if (hint.low > hint.high) std::swap(hint.low, hint.high);  // a negative slope
            hint.visible = ch.active;
            volume->channelHints.push_back(hint);
        }
    volume->dirty();
    OSG_INFO << path << ": OME-Zarr " << a.version << ", level " << level << " of " << levels << ", " << sizeText(size, blocks) << " "
             << array.metadata().dtype.str() << ", spacing " << spacing[0] << " " << spacing[1] << " " << spacing[2] << " "
             << image.spaceUnit() << std::endl;
    return volume;
}

std::uint64_t omeZarrLevelBytes(const std::string& path, std::size_t level)
{
    const OmeZarrImage image(path);
    const std::array<std::uint64_t, 3> s = image.size(level);
    std::uint64_t bytes = image.level(level).voxelBytes();
    for (const std::uint64_t n : {s[0], s[1], s[2], image.channels(), image.frames()}) {
        if (n != 0 && bytes > UINT64_MAX / n) return UINT64_MAX;
        bytes *= n;
    }
    return bytes;
}

osg::ref_ptr<Volume> openOmeZarrVolumeLazily(const std::string& path, std::uint64_t previewBudget, std::uint64_t cacheBudget,
                                             const osgDB::Options* options)
{
    osg::ref_ptr<OmeZarrSource> source = new OmeZarrSource(path, std::size_t(cacheBudget), previewBudget, 0, 0, options);
    const OmeZarrImage& image = source->image();
    const int level = previewLevelFor(*source, previewBudget);
    const osg::Vec3i dims = source->levelDims(level), full = source->levelDims(0);
    osg::ref_ptr<Volume> volume = new Volume;
    volume->allocate(source->type(), dims);
    if (level < source->fileLevelCount())
        image.level(std::size_t(level)).readRegion(source->box(level, {0, 0, 0}, dims), volume->data(), loadProgressOf(options));
    else
        source->read(level, {0, 0, 0}, dims, volume->data());

    // The preview covers level 0's box exactly; its voxel centres sit inside that box.
    const osg::Vec3d spacing0 = source->spacing();
    const osg::Vec3d spacing(spacing0.x() * full.x() / dims.x(), spacing0.y() * full.y() / dims.y(), spacing0.z() * full.z() / dims.z());
    const std::array<double, 3> origin0 = image.origin(0);
    const osg::Vec3d origin = osg::Vec3d(origin0[0], origin0[1], origin0[2]) + (spacing - spacing0) * 0.5;
    volume->setSpacing(spacing);
    const OmeZarrAttributes& a = image.attributes();
    volume->setRescale(a.rescaleSlope, a.rescaleIntercept);
    setImageUserValues(*volume, image, 0, spacing, origin);
    volume->sourceFile = path;
    volume->setFullResolution(source.get(), level);
    volume->dirty();
    if (image.channels() > 1 || image.frames() > 1)
        OSG_NOTICE << path << ": opened lazily; only channel 0, time point 0 of " << image.channels() << " channels and " << image.frames()
                   << " time points is read" << std::endl;
    OSG_NOTICE << path << ": opened lazily, level 0 " << full.x() << "x" << full.y() << "x" << full.z() << " read on demand; level " << level
               << " of " << source->levelCount() << " (" << dims.x() << "x" << dims.y() << "x" << dims.z() << ") in memory" << std::endl;
    return volume;
}

}  // namespace volren::omezarr
