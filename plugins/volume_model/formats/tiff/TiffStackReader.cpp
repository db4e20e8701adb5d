#include "TiffStackReader.h"

#include "ImageJDisplay.h"
#include "ImageJMetadata.h"
#include "OmeMetadata.h"
#include "SpacingOption.h"
#include "StackLayout.h"
#include "TiffFile.h"
#include "TiffPage.h"

#include <algorithm>
#include <volume_model/LengthUnit.h>
#include <volume_model/LoadProgress.h>

#include <osg/Notify>
#include <osg/ValueObject>

#include <cmath>
#include <cstring>
#include <memory>
#include <stdexcept>

namespace volren::tiff {

namespace {

/// One page to stack: which file, which directory, what it holds.
struct PageRef
{
    std::size_t file = 0;
    tdir_t directory = 0;
    PageFormat format;
};

/// Metadata of the first page that gives the geometry.
struct FirstPage
{
    std::string description;
    std::optional<double> xSpacing, ySpacing;
    std::vector<std::uint32_t> imageJCounts;  ///< IJMetadata byte counts (tag 50838), when present
    std::vector<std::uint8_t> imageJData;     ///< IJMetadata (tag 50839), when present
};

std::optional<double> spacingFromResolution(TIFF* tif, ttag_t tag)
{
    float resolution = 0.0f;
    if (!TIFFGetField(tif, tag, &resolution)) return std::nullopt;
    if (!(resolution > 0.0f) || !std::isfinite(resolution)) return std::nullopt;
    return 1.0 / double(resolution);
}

FirstPage readFirstPage(TIFF* tif)
{
    FirstPage first;
    char* text = nullptr;
    if (TIFFGetField(tif, TIFFTAG_IMAGEDESCRIPTION, &text) && text) first.description = text;
    first.xSpacing = spacingFromResolution(tif, TIFFTAG_XRESOLUTION);
    first.ySpacing = spacingFromResolution(tif, TIFFTAG_YRESOLUTION);
    // ImageJ's private tags, which libtiff keeps as anonymous fields (a count, then the values).
    // Their values are only read as the types ImageJ writes (a file may declare any type).
    auto typed = [tif](unsigned int tag, std::initializer_list<TIFFDataType> types) {
        const TIFFField* field = TIFFFindField(tif, tag, TIFF_ANY);
        return field && std::find(types.begin(), types.end(), TIFFFieldDataType(field)) != types.end();
    };
    std::uint32_t count = 0;
    const std::uint32_t* counts = nullptr;
    const std::uint8_t* data = nullptr;
    if (typed(imageJMetadataCountsTag, {TIFF_LONG}) && TIFFGetField(tif, imageJMetadataCountsTag, &count, &counts) && counts)
        first.imageJCounts.assign(counts, counts + count);
    if (typed(imageJMetadataTag, {TIFF_BYTE, TIFF_UNDEFINED}) && TIFFGetField(tif, imageJMetadataTag, &count, &data) && data)
        first.imageJData.assign(data, data + count);
    return first;
}

/// Lists the full-resolution pages of `path` (reduced-resolution pages are skipped), checking
/// that each lies inside the file and matches `reference` (the first page of the stack).
void collectPages(const std::string& path, std::size_t fileIndex, std::vector<PageRef>& pages, FirstPage* first)
{
    TiffFile file(path);
    TIFF* tif = file.handle();
    tdir_t directory = 0;
    for (;;) {
        std::uint32_t subfileType = 0;
        TIFFGetFieldDefaulted(tif, TIFFTAG_SUBFILETYPE, &subfileType);
        if (first && pages.empty()) *first = readFirstPage(tif);
        if (subfileType & FILETYPE_REDUCEDIMAGE) {
            OSG_INFO << path << ": skipping reduced-resolution page " << directory << std::endl;
        } else {
            PageRef ref{fileIndex, directory, readPageFormat(file, pages.size())};
            if (!pages.empty() && !pages.front().format.sameLayout(ref.format))
                throw std::runtime_error(path + ": page " + std::to_string(pages.size()) + " (" + ref.format.describe() +
                                         ") differs from page 0 (" + pages.front().format.describe() + ")");
            checkPageExtent(file, ref.format, pages.size());
            pages.push_back(ref);
        }
        if (!TIFFReadDirectory(tif)) {
            const std::string error = file.takeError();
            if (!error.empty())
                throw std::runtime_error(path + ": truncated or corrupt file: cannot read page " +
                                         std::to_string(pages.size()) + ": " + error);
            break;
        }
        ++directory;
    }
    if (pages.empty()) throw std::runtime_error(path + ": no full-resolution pages");
}

}  // namespace

osg::ref_ptr<Volume> readTiffStack(const std::vector<std::string>& files, const std::string& name,
                                   const osgDB::Options* options)
{
    if (files.empty()) throw std::runtime_error(name + ": zero pages: no TIFF files");
    const std::optional<osg::Vec3d> spacingOverride = [&] {
        try {
            return stack::spacingOption(options);
        } catch (const std::exception& e) {
            throw std::runtime_error(name + ": " + e.what());
        }
    }();

    // Pass 1: every page's format, before allocating anything.
    std::vector<PageRef> pages;
    FirstPage first;
    for (std::size_t i = 0; i < files.size(); ++i) collectPages(files[i], i, pages, i == 0 ? &first : nullptr);
    const PageFormat& format = pages.front().format;
    const std::size_t spp = format.samplesPerPixel;

    StackLayout layout;
    layout.slices = pages.size();
    std::optional<double> zSpacing;
    std::string unit;  // of the spacing, as the file names it
    std::vector<ChannelHint> displayHints;
    std::string metadata = files.size() > 1 ? "numbered slices" : "plain TIFF";
    if (files.size() == 1 && isOmeDescription(first.description)) {
        const OmeMetadata ome = parseOmeDescription(first.description, name);
        if (ome.images > 1) OSG_WARN << name << ": OME-XML describes " << ome.images << " images; volren reads the first" << std::endl;
        if (ome.sizeX != format.width || ome.sizeY != format.height)
            throw std::runtime_error(name + ": OME-XML says SizeX=" + std::to_string(ome.sizeX) + " SizeY=" +
                                     std::to_string(ome.sizeY) + " but pages are " + format.describe());
        layout = omeLayout(ome, pages.size(), spp, name);
        if (ome.physicalX) first.xSpacing = ome.physicalX;
        if (ome.physicalY) first.ySpacing = ome.physicalY;
        zSpacing = ome.physicalZ;
        unit = ome.physicalUnit;
        metadata = "OME-XML, DimensionOrder XY" + ome.order;
        if (spp == 1 && ome.channels.size() == layout.channels) displayHints = ome.channels;
    } else if (isImageJDescription(first.description)) {
        const ImageJMetadata ij = parseImageJDescription(first.description, name);
        if (files.size() == 1) layout = imageJLayout(ij, pages.size(), name);
        zSpacing = ij.spacing;
        unit = ij.unit;
        metadata = "ImageJ" + std::string(ij.unit.empty() ? "" : ", unit " + ij.unit);
        if (!first.imageJData.empty())
            displayHints = parseImageJDisplay(first.imageJCounts, first.imageJData, layout.channels * spp, name);
    }

    const int channels = int(layout.channels * spp);
    const osg::Vec3i dims(int(format.width), int(format.height), int(layout.slices));
    osg::ref_ptr<Volume> volume = new Volume;
    try {
        if (format.width > 2147483647u || format.height > 2147483647u || layout.slices > 2147483647u ||
            layout.frames > 2147483647u || layout.channels * spp > 2147483647u)
            throw std::invalid_argument("dimensions exceed the int range");
        volume->allocate(format.type, dims, channels, int(layout.frames));
    } catch (const std::bad_alloc&) {
        throw std::runtime_error(name + ": not enough memory for " + format.describe() + " x " + std::to_string(pages.size()) + " pages");
    } catch (const std::invalid_argument& e) {
        throw std::runtime_error(name + ": " + e.what());
    }

    // Pass 2: decode each page into its block and slice.
    const std::size_t sliceBytes = std::size_t(format.width) * format.height * voxelSize(format.type);
    std::unique_ptr<TiffFile> file;
    std::vector<std::uint8_t> planes;
    for (std::size_t p = 0; p < pages.size(); ++p) {
        const PageRef& ref = pages[p];
        if (!file || file->path() != files[ref.file]) {
            file.reset();
            file = std::make_unique<TiffFile>(files[ref.file]);
        }
        if (!TIFFSetDirectory(file->handle(), ref.directory)) file->fail("cannot read page " + std::to_string(p));
        readPageSamples(*file, readPageFormat(*file, p), p, planes);
        std::size_t c = 0, z = 0, t = 0;
        layout.coordinates(p, c, z, t);
        for (std::size_t s = 0; s < spp; ++s)
            std::memcpy(volume->block(int(c * spp + s), int(t)) + z * sliceBytes, planes.data() + s * sliceBytes, sliceBytes);
        if (!reportLoadProgress(options, double(p + 1), double(pages.size())))
            throw std::runtime_error(name + ": cancelled");
    }

    osg::Vec3d spacing(first.xSpacing.value_or(1.0), first.ySpacing.value_or(first.xSpacing.value_or(1.0)),
                       zSpacing.value_or(1.0));
    if (spacingOverride) spacing = *spacingOverride;
    volume->setSpacing(spacing);
    volume->dirty();
    volume->sourceFile = name;
    volume->setName(name);
    volume->channelHints = std::move(displayHints);
    if (!spacingOverride && !lengthUnitSymbol(unit).empty()) volume->setUserValue(spacingUnitKey, unit);
    if (format.widenToFloat) OSG_NOTICE << name << ": 32-bit integer samples stored as float32" << std::endl;
    OSG_INFO << name << ": " << metadata << ", " << dims.x() << "x" << dims.y() << "x" << dims.z() << " "
             << voxelTypeName(format.type) << ", " << channels << " channel(s), " << layout.frames << " frame(s)" << std::endl;
    if (format.type == VoxelType::Float32 && volume->nonFiniteCount() > 0)
        OSG_WARN << name << ": " << volume->nonFiniteCount() << " NaN/Inf voxels; they are treated as empty" << std::endl;
    return volume;
}

}  // namespace volren::tiff
