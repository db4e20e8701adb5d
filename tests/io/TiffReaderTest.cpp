// TIFF stack loader: the shared ImageJ hyperstacks (expected values from the MANIFEST and from
// an independent parse of the files), generated files for every encoding the reader supports,
// ImageJ / OME-XML layouts, numbered slice folders, bad files, progress and cancellation.
#include "TestData.h"

#include <volume_model/ChannelDisplay.h>
#include <volume_model/LengthUnit.h>
#include <volume_model/LoadProgress.h>
#include <volume_model/ReadVolume.h>

#include <osg/Image>
#include <osgDB/ReadFile>
#include <osgDB/Registry>
#include <gtest/gtest.h>
#include <tiffio.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>

namespace volren::test {
namespace {

/// How a generated test TIFF is encoded.
struct TiffSpec
{
    std::uint32_t width = 37, height = 23;
    std::uint16_t bits = 16, sampleFormat = SAMPLEFORMAT_UINT, samples = 1;
    std::uint16_t planar = PLANARCONFIG_CONTIG, compression = COMPRESSION_NONE;
    std::uint32_t tile = 0;          ///< tile edge (multiple of 16); 0 writes strips
    std::uint32_t rowsPerStrip = 5;
    std::string description;         ///< ImageDescription of page 0
    float resolution = 0.0f;         ///< X/YResolution of every page (0: none)
};

/// Value of sample `s` at (x, y) of page `page`: distinct per page, signed for signed types.
using SampleValue = std::function<double(int page, int x, int y, int s)>;

double defaultValue(const TiffSpec& spec, int page, int x, int y, int s)
{
    double v = double((page * 7 + x * 3 + y * 5 + s * 11) % 100);
    if (spec.sampleFormat == SAMPLEFORMAT_INT) v -= 50.0;
    if (spec.sampleFormat == SAMPLEFORMAT_IEEEFP) v = v * 0.5 - 10.25;
    return v;
}

void putSample(std::uint8_t* dst, const TiffSpec& spec, double v)
{
    const bool isSigned = spec.sampleFormat == SAMPLEFORMAT_INT;
    if (spec.sampleFormat == SAMPLEFORMAT_IEEEFP && spec.bits == 32) {
        const float f = float(v);
        std::memcpy(dst, &f, 4);
    } else if (spec.sampleFormat == SAMPLEFORMAT_IEEEFP && spec.bits == 64) {
        std::memcpy(dst, &v, 8);
    } else if (spec.bits == 8) {
        const auto b = isSigned ? std::uint8_t(std::int8_t(v)) : std::uint8_t(v);
        std::memcpy(dst, &b, 1);
    } else if (spec.bits == 16) {
        const auto b = isSigned ? std::uint16_t(std::int16_t(v)) : std::uint16_t(v);
        std::memcpy(dst, &b, 2);
    } else if (spec.bits == 32) {
        const auto b = isSigned ? std::uint32_t(std::int32_t(v)) : std::uint32_t(v);
        std::memcpy(dst, &b, 4);
    }
}

/// Writes `specs.size()` pages, page p encoded as specs[p], with values from `value`.
void writeTiff(const std::string& path, const std::vector<TiffSpec>& specs, const SampleValue& value)
{
    TIFF* tif = TIFFOpen(path.c_str(), "w");
    ASSERT_NE(tif, nullptr) << path;
    for (std::size_t p = 0; p < specs.size(); ++p) {
        const TiffSpec& s = specs[p];
        TIFFSetField(tif, TIFFTAG_IMAGEWIDTH, s.width);
        TIFFSetField(tif, TIFFTAG_IMAGELENGTH, s.height);
        TIFFSetField(tif, TIFFTAG_BITSPERSAMPLE, s.bits);
        TIFFSetField(tif, TIFFTAG_SAMPLESPERPIXEL, s.samples);
        TIFFSetField(tif, TIFFTAG_SAMPLEFORMAT, s.sampleFormat);
        TIFFSetField(tif, TIFFTAG_PLANARCONFIG, s.planar);
        TIFFSetField(tif, TIFFTAG_COMPRESSION, s.compression);
        TIFFSetField(tif, TIFFTAG_PHOTOMETRIC, s.samples >= 3 ? PHOTOMETRIC_RGB : PHOTOMETRIC_MINISBLACK);
        if (s.samples == 4) {
            const std::uint16_t extra = EXTRASAMPLE_UNASSALPHA;
            TIFFSetField(tif, TIFFTAG_EXTRASAMPLES, 1, &extra);
        }
        if (p == 0 && !s.description.empty()) TIFFSetField(tif, TIFFTAG_IMAGEDESCRIPTION, s.description.c_str());
        if (s.resolution > 0) {
            TIFFSetField(tif, TIFFTAG_XRESOLUTION, s.resolution);
            TIFFSetField(tif, TIFFTAG_YRESOLUTION, s.resolution);
            TIFFSetField(tif, TIFFTAG_RESOLUTIONUNIT, RESUNIT_NONE);
        }
        const bool separate = s.planar == PLANARCONFIG_SEPARATE;
        const std::uint32_t chunkSamples = separate ? 1 : s.samples;
        const std::size_t bytes = (s.bits + 7) / 8;
        const std::uint32_t cw = s.tile ? s.tile : s.width, ch = s.tile ? s.tile : s.rowsPerStrip;
        if (s.tile) {
            TIFFSetField(tif, TIFFTAG_TILEWIDTH, s.tile);
            TIFFSetField(tif, TIFFTAG_TILELENGTH, s.tile);
        } else {
            TIFFSetField(tif, TIFFTAG_ROWSPERSTRIP, s.rowsPerStrip);
        }
        for (std::uint16_t plane = 0; plane < (separate ? s.samples : 1); ++plane)
            for (std::uint32_t y0 = 0; y0 < s.height; y0 += ch)
                for (std::uint32_t x0 = 0; x0 < s.width; x0 += cw) {
                    const std::uint32_t rows = s.tile ? ch : std::min(ch, s.height - y0);
                    std::vector<std::uint8_t> buf(std::size_t(cw) * rows * chunkSamples * bytes, 0);
                    for (std::uint32_t y = 0; y < rows && y0 + y < s.height; ++y)
                        for (std::uint32_t x = 0; x < cw && x0 + x < s.width; ++x)
                            for (std::uint32_t k = 0; k < chunkSamples; ++k)
                                putSample(buf.data() + ((std::size_t(y) * cw + x) * chunkSamples + k) * bytes, s,
                                          value(int(p), int(x0 + x), int(y0 + y), int(separate ? plane : k)));
                    const tmsize_t n = tmsize_t(buf.size());
                    const tmsize_t written =
                        s.tile ? TIFFWriteEncodedTile(tif, TIFFComputeTile(tif, x0, y0, 0, plane), buf.data(), n)
                               : TIFFWriteEncodedStrip(tif, TIFFComputeStrip(tif, y0, plane), buf.data(), n);
                    ASSERT_GE(written, 0) << path;
                }
        ASSERT_TRUE(TIFFWriteDirectory(tif)) << path;
    }
    TIFFClose(tif);
}

void writeTiff(const std::string& path, const TiffSpec& spec, int pages)
{
    writeTiff(path, std::vector<TiffSpec>(std::size_t(pages), spec),
              [&](int p, int x, int y, int s) { return defaultValue(spec, p, x, y, s); });
}

/// Stored value of (x, y, z) in block (c, t).
double at(const Volume& v, int c, int t, int x, int y, int z)
{
    const osg::Vec3i& d = v.dims();
    return v.storedValue(std::size_t(t * v.channels() + c) * v.voxelCount() + std::size_t(x) +
                         std::size_t(d.x()) * (std::size_t(y) + std::size_t(d.y()) * std::size_t(z)));
}

/// Sum of slice z of block (c, t).
double sliceSum(const Volume& v, int c, int t, int z)
{
    double sum = 0.0;
    for (int y = 0; y < v.dims().y(); ++y)
        for (int x = 0; x < v.dims().x(); ++x) sum += at(v, c, t, x, y, z);
    return sum;
}

double blockSum(const Volume& v, int c, int t)
{
    double sum = 0.0;
    for (int z = 0; z < v.dims().z(); ++z) sum += sliceSum(v, c, t, z);
    return sum;
}


/// The volren reader osgDB picks for .tif (after volren's plugin folder is registered).
osgDB::ReaderWriter* tiffPlugin()
{
    registerPluginPath();
    return osgDB::Registry::instance()->getReaderWriterForExtension("tif");
}

/// Reads a directory or wildcard pattern through the volren TIFF plugin (readVolumeFile takes
/// files only).
osgDB::ReaderWriter::ReadResult readStack(const std::string& dirOrPattern, const osgDB::Options* options = nullptr)
{
    return tiffPlugin()->readObject(dirOrPattern, options);
}

void expectMentions(const std::string& message, const std::string& file, const std::string& reason)
{
    EXPECT_NE(message.find(file), std::string::npos) << message;
    EXPECT_NE(message.find(reason), std::string::npos) << message;
}

// Expected sums: computed with a stand-alone pure-Python script (struct
// module only) that walks the IFD chain, concatenates each page's uncompressed StripOffsets /
// StripByteCounts bytes and sums the little-endian uint16 samples; it shares no code with libtiff
// or this reader. Page p of the 2-channel file is channel p % 2, slice p / 2 (ImageJ XYCZT).

TEST(TiffReader, ReadsChromosomeStackAsInTheManifest)
{
    VOLREN_REQUIRE_SHARED_DATA();
    const std::string path = sharedData("microscopy/xyz_8bit__chromosomes.tif");
    osg::ref_ptr<Volume> v = readVolumeFile(path);
    EXPECT_EQ(v->dims(), osg::Vec3i(126, 152, 40));
    EXPECT_EQ(v->type(), VoxelType::UInt16);
    EXPECT_EQ(v->channels(), 1);
    EXPECT_EQ(v->frames(), 1);
    EXPECT_NEAR(v->spacing().x(), 0.03385, 1e-5);  // 1 / 29.53846
    EXPECT_NEAR(v->spacing().y(), 0.03385, 1e-5);
    EXPECT_NEAR(v->spacing().z(), 0.15, 1e-9);
    EXPECT_EQ(v->sourceFile, path);
    EXPECT_EQ(sliceSum(*v, 0, 0, 0), 2188493.0);   // page 0
    EXPECT_EQ(sliceSum(*v, 0, 0, 39), 2249557.0);  // page 39 (last)
    EXPECT_EQ(blockSum(*v, 0, 0), 93054994.0);     // all 40 pages
}

TEST(TiffReader, ReadsCalibratedGolgiStackAsInTheManifest)
{
    VOLREN_REQUIRE_SHARED_DATA();
    osg::ref_ptr<Volume> v = readVolumeFile(sharedData("microscopy/xyz_calibrated_16bit__golgi_bfa.tif"));
    EXPECT_EQ(v->dims(), osg::Vec3i(147, 137, 25));
    EXPECT_EQ(v->type(), VoxelType::UInt16);
    EXPECT_EQ(v->channels(), 1);
    EXPECT_NEAR(v->spacing().x(), 0.3514, 1e-4);  // 1 / 2.845474
    EXPECT_NEAR(v->spacing().y(), 0.3514, 1e-4);
    EXPECT_NEAR(v->spacing().z(), 0.3876, 1e-9);
    EXPECT_EQ(sliceSum(*v, 0, 0, 0), 264320.0);   // page 0
    EXPECT_EQ(sliceSum(*v, 0, 0, 24), 658091.0);  // page 24 (last)
    EXPECT_EQ(blockSum(*v, 0, 0), 28822807.0);    // all 25 pages
}

TEST(TiffReader, ReadsTwoChannelDnaHyperstackAsInTheManifest)
{
    VOLREN_REQUIRE_SHARED_DATA();
    osg::ref_ptr<Volume> v = readVolumeFile(sharedData("microscopy/xyzc_16bit__dna_conf_wf.tif"));
    EXPECT_EQ(v->dims(), osg::Vec3i(133, 130, 45));
    EXPECT_EQ(v->type(), VoxelType::UInt16);
    EXPECT_EQ(v->channels(), 2);
    EXPECT_EQ(v->frames(), 1);
    EXPECT_NEAR(v->spacing().x(), 0.5119, 1e-4);  // 1 / 1.953591
    EXPECT_NEAR(v->spacing().y(), 0.5119, 1e-4);
    EXPECT_NEAR(v->spacing().z(), 0.4994, 1e-4);
    EXPECT_EQ(lengthUnitOf(*v), "\xC2\xB5m") << "ImageJ unit=micron";
    EXPECT_EQ(sliceSum(*v, 0, 0, 0), 213017.0);     // page 0: confocal, z 0
    EXPECT_EQ(sliceSum(*v, 1, 0, 0), 16688374.0);   // page 1: widefield, z 0
    EXPECT_EQ(sliceSum(*v, 0, 0, 44), 652374.0);    // page 88: confocal, z 44
    EXPECT_EQ(sliceSum(*v, 1, 0, 44), 16566660.0);  // page 89 (last): widefield, z 44
    EXPECT_EQ(blockSum(*v, 0, 0), 348677558.0);     // even pages
    EXPECT_EQ(blockSum(*v, 1, 0), 750937956.0);     // odd pages
}

TEST(TiffReader, TheDnaHyperstacksLutsAndDisplayRangesBecomeChannelHints)
{
    // Its IJMetadata (tags 50838/50839): channel 0 the Magenta LUT over 0..65535 (ImageJ's range
    // when none was set), channel 1 the Green LUT over 624..6281.91015625.
    VOLREN_REQUIRE_SHARED_DATA();
    osg::ref_ptr<Volume> v = readVolumeFile(sharedData("microscopy/xyzc_16bit__dna_conf_wf.tif"));
    ASSERT_EQ(v->channelHints.size(), 2u);
    const ChannelHint &confocal = v->channelHints[0], &widefield = v->channelHints[1];
    ASSERT_EQ(confocal.colours.size(), 256u);
    EXPECT_EQ(confocal.colours[0], osg::Vec3f(0, 0, 0));
    EXPECT_EQ(confocal.colours[128], osg::Vec3f(128 / 255.f, 0, 128 / 255.f));
    EXPECT_EQ(confocal.colours[255], osg::Vec3f(1, 0, 1));
    EXPECT_TRUE(confocal.hasWindow);
    EXPECT_EQ(confocal.low, 0.0);
    EXPECT_EQ(confocal.high, 65535.0);
    ASSERT_EQ(widefield.colours.size(), 256u);
    EXPECT_EQ(widefield.colours[255], osg::Vec3f(0, 1, 0));
    EXPECT_EQ(widefield.low, 624.0);
    EXPECT_EQ(widefield.high, 6281.91015625);
    // The default display: the file's LUTs; channel 1 over its range, channel 0 (no range set)
    // from its background to its 99.5th percentile.
    const std::vector<ChannelDisplay> shown = defaultChannelDisplays(*v);
    ASSERT_EQ(shown.size(), 2u);
    const TransferFunction &tf0 = *shown[0].transferFunction, &tf1 = *shown[1].transferFunction;
    EXPECT_EQ(tf1.points().begin()->first, 624.0);
    EXPECT_EQ(tf1.points().rbegin()->first, 6281.91015625);
    EXPECT_EQ(tf1.evaluate(7000.0), osg::Vec4(0, 1, 0, float(defaultChannelOpacity)));
    EXPECT_GT(tf0.points().begin()->first, 0.0);
    EXPECT_LT(tf0.points().rbegin()->first, 65535.0);
    const osg::Vec4 top = tf0.evaluate(65535.0);
    EXPECT_EQ(osg::Vec3(top.r(), top.g(), top.b()), osg::Vec3(1, 0, 1)) << "magenta, the file's LUT";
}

TEST(TiffReader, BrokenImageJDisplayMetadataIsIgnoredWithAWarning)
{
    // Display hints only decide colours: a bad IJMetadata block leaves the voxels as they are.
    VOLREN_REQUIRE_SHARED_DATA();
    std::ifstream in(sharedData("microscopy/xyzc_16bit__dna_conf_wf.tif"), std::ios::binary);
    const std::string original((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::size_t header = original.find("IJIJinfo");
    ASSERT_NE(header, std::string::npos);
    const std::size_t luts = original.find(std::string("luts\0\0\0\2", 8), header);
    ASSERT_NE(luts, std::string::npos);
    const std::string dir = tempDirectory();
    for (const auto& [at, bytes] : {std::pair(header, std::string("XXXX")), std::pair(luts + 4, std::string("\x7f\xff\xff\xff"))}) {
        std::string broken = original;
        broken.replace(at, bytes.size(), bytes);
        const std::string path = dir + "/broken.tif";
        writeFile(path, broken);
        osg::ref_ptr<Volume> v = readVolumeFile(path);
        EXPECT_TRUE(v->channelHints.empty());
        EXPECT_EQ(v->channels(), 2);
        EXPECT_EQ(blockSum(*v, 1, 0), 750937956.0);
    }
}

TEST(TiffReader, VolrenPluginShadowsOsgsOwnTiffPluginForObjectsImagesAndNodes)
{
    VOLREN_REQUIRE_SHARED_DATA();
    const std::string path = sharedData("microscopy/xyz_8bit__chromosomes.tif");
    ASSERT_NE(tiffPlugin(), nullptr);
    EXPECT_STREQ(tiffPlugin()->className(), "volren TIFF stack reader");
    EXPECT_STREQ(osgDB::Registry::instance()->getReaderWriterForExtension("tiff")->className(), "volren TIFF stack reader");
    osg::ref_ptr<osg::Object> object = osgDB::readRefObjectFile(path);
    auto* v = dynamic_cast<Volume*>(object.get());
    ASSERT_NE(v, nullptr) << "osgDB::readRefObjectFile did not give a volren::Volume";
    EXPECT_EQ(v->dims(), osg::Vec3i(126, 152, 40));
    osg::ref_ptr<osg::Image> image = osgDB::readRefImageFile(path);
    ASSERT_TRUE(image.valid());
    EXPECT_EQ(image->s(), 126);
    EXPECT_EQ(image->t(), 152);
    EXPECT_EQ(image->r(), 40);
    EXPECT_TRUE(osgDB::readRefNodeFile(path).valid()) << "a bare volume read as a node gets the default scene";
}

/// One encoding: sample type, compression, strips or tiles.
struct Encoding
{
    const char* name;
    std::uint16_t bits, sampleFormat, compression;
    std::uint32_t tile;
    VoxelType expected;
};

void PrintTo(const Encoding& e, std::ostream* out) { *out << e.name; }

class TiffReaderEncoding : public ::testing::TestWithParam<Encoding>
{
};

TEST_P(TiffReaderEncoding, ReadsEveryVoxelOfEveryPage)
{
    const Encoding& e = GetParam();
    TiffSpec spec;
    spec.bits = e.bits;
    spec.sampleFormat = e.sampleFormat;
    spec.compression = e.compression;
    spec.tile = e.tile;
    const std::string path = tempDirectory() + "/stack.tif";
    writeTiff(path, spec, 4);
    osg::ref_ptr<Volume> v = readVolumeFile(path);
    ASSERT_EQ(v->dims(), osg::Vec3i(37, 23, 4));
    EXPECT_EQ(v->type(), e.expected);
    EXPECT_EQ(v->channels(), 1);
    EXPECT_EQ(v->spacing(), osg::Vec3d(1, 1, 1));
    for (int z = 0; z < 4; ++z)
        for (int y = 0; y < 23; ++y)
            for (int x = 0; x < 37; ++x)
                ASSERT_EQ(at(*v, 0, 0, x, y, z), defaultValue(spec, z, x, y, 0)) << x << "," << y << "," << z;
}

INSTANTIATE_TEST_SUITE_P(TiffEncodings, TiffReaderEncoding,
    ::testing::Values(
        Encoding{"uint8_none_strips", 8, SAMPLEFORMAT_UINT, COMPRESSION_NONE, 0, VoxelType::UInt8},
        Encoding{"int8_lzw_tiles", 8, SAMPLEFORMAT_INT, COMPRESSION_LZW, 16, VoxelType::Int8},
        Encoding{"uint16_none_tiles", 16, SAMPLEFORMAT_UINT, COMPRESSION_NONE, 16, VoxelType::UInt16},
        Encoding{"uint16_lzw_strips", 16, SAMPLEFORMAT_UINT, COMPRESSION_LZW, 0, VoxelType::UInt16},
        Encoding{"uint16_deflate_tiles", 16, SAMPLEFORMAT_UINT, COMPRESSION_ADOBE_DEFLATE, 32, VoxelType::UInt16},
        Encoding{"int16_deflate_strips", 16, SAMPLEFORMAT_INT, COMPRESSION_ADOBE_DEFLATE, 0, VoxelType::Int16},
        Encoding{"int16_lzw_tiles", 16, SAMPLEFORMAT_INT, COMPRESSION_LZW, 16, VoxelType::Int16},
        Encoding{"float32_none_strips", 32, SAMPLEFORMAT_IEEEFP, COMPRESSION_NONE, 0, VoxelType::Float32},
        Encoding{"float32_deflate_tiles", 32, SAMPLEFORMAT_IEEEFP, COMPRESSION_ADOBE_DEFLATE, 16, VoxelType::Float32},
        Encoding{"float32_lzw_strips", 32, SAMPLEFORMAT_IEEEFP, COMPRESSION_LZW, 0, VoxelType::Float32},
        Encoding{"uint32_none_strips_as_float", 32, SAMPLEFORMAT_UINT, COMPRESSION_NONE, 0, VoxelType::Float32},
        Encoding{"int32_deflate_tiles_as_float", 32, SAMPLEFORMAT_INT, COMPRESSION_ADOBE_DEFLATE, 16, VoxelType::Float32}),
    [](const ::testing::TestParamInfo<Encoding>& info) { return std::string(info.param.name); });

TEST(TiffReader, RgbPagesBecomeThreeChannelsInBothPlanarConfigurations)
{
    const std::string dir = tempDirectory();
    for (std::uint16_t planar : {PLANARCONFIG_CONTIG, PLANARCONFIG_SEPARATE}) {
        TiffSpec spec;
        spec.bits = 8;
        spec.samples = 3;
        spec.planar = planar;
        spec.compression = COMPRESSION_LZW;
        const std::string path = dir + "/rgb" + std::to_string(planar) + ".tif";
        writeTiff(path, spec, 3);
        osg::ref_ptr<Volume> v = readVolumeFile(path);
        ASSERT_EQ(v->channels(), 3) << path;
        ASSERT_EQ(v->dims(), osg::Vec3i(37, 23, 3));
        for (int c = 0; c < 3; ++c)
            for (int z = 0; z < 3; ++z)
                for (int y = 0; y < 23; y += 4)
                    for (int x = 0; x < 37; x += 3)
                        ASSERT_EQ(at(*v, c, 0, x, y, z), defaultValue(spec, z, x, y, c)) << path;
    }
}

TEST(TiffReader, ImageJHyperstackGivesChannelsFramesAndSpacing)
{
    TiffSpec spec;
    spec.bits = 8;
    spec.resolution = 4.0f;  // 4 pixels per unit: spacing 0.25
    spec.description = "ImageJ=1.54f\nimages=12\nchannels=2\nslices=3\nframes=2\nhyperstack=true\nunit=micron\nspacing=2.5\n";
    const std::string path = tempDirectory() + "/hyper.tif";
    writeTiff(path, std::vector<TiffSpec>(12, spec), [](int p, int, int, int) { return double(p); });
    osg::ref_ptr<Volume> v = readVolumeFile(path);
    EXPECT_EQ(v->dims(), osg::Vec3i(37, 23, 3));
    EXPECT_EQ(v->channels(), 2);
    EXPECT_EQ(v->frames(), 2);
    EXPECT_EQ(v->spacing(), osg::Vec3d(0.25, 0.25, 2.5));
    for (int t = 0; t < 2; ++t)
        for (int z = 0; z < 3; ++z)
            for (int c = 0; c < 2; ++c) EXPECT_EQ(at(*v, c, t, 5, 7, z), double(c + 2 * (z + 3 * t))) << c << z << t;
}

TEST(TiffReader, OmeTiffGivesLayoutFromDimensionOrderAndPhysicalSizes)
{
    TiffSpec spec;
    spec.bits = 16;
    spec.description =
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?><OME xmlns=\"http://www.openmicroscopy.org/Schemas/OME/2016-06\">"
        "<Image ID=\"Image:0\"><Pixels ID=\"Pixels:0\" DimensionOrder=\"XYZTC\" Type=\"uint16\" SizeX=\"37\" "
        "SizeY=\"23\" SizeZ=\"3\" SizeC=\"2\" SizeT=\"2\" PhysicalSizeX=\"0.2\" PhysicalSizeY=\"0.3\" "
        "PhysicalSizeZ=\"1.5\"><Channel ID=\"Channel:0:0\" SamplesPerPixel=\"1\"/></Pixels></Image></OME>";
    const std::string path = tempDirectory() + "/image.ome.tif";
    writeTiff(path, std::vector<TiffSpec>(12, spec), [](int p, int, int, int) { return double(p); });
    osg::ref_ptr<Volume> v = readVolumeFile(path);
    EXPECT_EQ(v->dims(), osg::Vec3i(37, 23, 3));
    EXPECT_EQ(v->channels(), 2);
    EXPECT_EQ(v->frames(), 2);
    EXPECT_EQ(v->spacing(), osg::Vec3d(0.2, 0.3, 1.5));
    EXPECT_EQ(lengthUnitOf(*v), "\xC2\xB5m") << "OME's default PhysicalSizeXUnit";
    for (int c = 0; c < 2; ++c)
        for (int t = 0; t < 2; ++t)
            for (int z = 0; z < 3; ++z) EXPECT_EQ(at(*v, c, t, 1, 2, z), double(z + 3 * (t + 2 * c))) << c << z << t;
    EXPECT_TRUE(v->channelHints.empty()) << "one <Channel> for two channels: no hints";
}

TEST(TiffReader, OmeTiffChannelNamesAndColoursBecomeChannelHints)
{
    // Color is a signed 32-bit RGBA integer: -16776961 = 0xFF0000FF (red), 16711935 = 0x00FF00FF (green).
    TiffSpec spec;
    spec.bits = 8;
    spec.description =
        "<OME><Image ID=\"Image:0\"><Pixels DimensionOrder=\"XYCZT\" SizeX=\"37\" SizeY=\"23\" SizeZ=\"2\" SizeC=\"2\" "
        "SizeT=\"1\"><Channel ID=\"Channel:0:0\" Name=\"DAPI\" Color=\"-16776961\"/><Channel ID=\"Channel:0:1\" "
        "Color=\"16711935\" Name=\"GFP\"/></Pixels></Image><Image ID=\"Image:1\"><Pixels SizeX=\"1\" SizeY=\"1\">"
        "<Channel Name=\"other\" Color=\"-1\"/></Pixels></Image></OME>";
    const std::string path = tempDirectory() + "/channels.ome.tif";
    writeTiff(path, std::vector<TiffSpec>(4, spec), [](int p, int, int, int) { return double(p); });
    osg::ref_ptr<Volume> v = readVolumeFile(path);
    ASSERT_EQ(v->channels(), 2);
    ASSERT_EQ(v->channelHints.size(), 2u) << "the second image's channel is not this one's";
    EXPECT_EQ(v->channelHints[0].name, "DAPI");
    EXPECT_EQ(v->channelHints[0].colours, std::vector<osg::Vec3f>{osg::Vec3f(1, 0, 0)});
    EXPECT_EQ(v->channelHints[1].name, "GFP");
    EXPECT_EQ(v->channelHints[1].colours, std::vector<osg::Vec3f>{osg::Vec3f(0, 1, 0)});
    EXPECT_FALSE(v->channelHints[0].hasWindow);
}

TEST(TiffReader, NumberedSlicesStackInNumericNotLexicalOrder)
{
    const std::string dir = tempDirectory();
    TiffSpec spec;
    spec.bits = 8;
    spec.width = 8;
    spec.height = 6;
    for (int n : {10, 2, 1, 9}) {
        writeTiff(dir + "/s" + std::to_string(n) + ".tif", std::vector<TiffSpec>{spec},
                  [n](int, int, int, int) { return double(n); });
    }
    std::ofstream(dir + "/notes.txt") << "not a slice";
    auto check = [&](osgDB::ReaderWriter::ReadResult result, const std::string& what) {
        auto* v = dynamic_cast<Volume*>(result.getObject());
        ASSERT_NE(v, nullptr) << what << ": " << result.message();
        ASSERT_EQ(v->dims(), osg::Vec3i(8, 6, 4)) << what;
        const double expected[] = {1, 2, 9, 10};
        for (int z = 0; z < 4; ++z) EXPECT_EQ(at(*v, 0, 0, 3, 3, z), expected[z]) << what << " z " << z;
    };
    check(readStack(dir), "directory");
    check(readStack(dir + "/s*.tif"), "pattern");
    registerPluginPath();
    osg::ref_ptr<osg::Object> object = osgDB::readRefObjectFile(dir + "/s*.tif");
    ASSERT_NE(dynamic_cast<Volume*>(object.get()), nullptr) << "osgDB::readRefObjectFile with a pattern";
    osg::ref_ptr<osgDB::Options> options = new osgDB::Options("spacing=0.5,0.5,3");
    osgDB::ReaderWriter::ReadResult spaced = readStack(dir, options.get());
    ASSERT_NE(dynamic_cast<Volume*>(spaced.getObject()), nullptr) << spaced.message();
    EXPECT_EQ(dynamic_cast<Volume*>(spaced.getObject())->spacing(), osg::Vec3d(0.5, 0.5, 3));
}

TEST(TiffReader, TruncatedFilesAreRejectedWithFileAndReason)
{
    const std::string dir = tempDirectory();
    for (std::uint16_t compression : {COMPRESSION_NONE, COMPRESSION_LZW}) {
        TiffSpec spec;
        spec.width = spec.height = 64;
        spec.compression = compression;
        const std::string whole = dir + "/whole" + std::to_string(compression) + ".tif";
        writeTiff(whole, spec, 4);
        std::ifstream in(whole, std::ios::binary);
        std::vector<char> bytes((std::istreambuf_iterator<char>(in)), {});
        // libtiff writes each page's data before its IFD: keep all IFDs, cut page 2's data.
        const std::string cut = dir + "/cut" + std::to_string(compression) + ".tif";
        std::filesystem::copy_file(whole, cut);
        std::filesystem::resize_file(cut, bytes.size() * 6 / 10);
        const std::string why = expectReadError(cut);
        EXPECT_NE(why.find(cut), std::string::npos) << why;
        EXPECT_NE(why.find("truncated or corrupt file: cannot read page 2"), std::string::npos) << why;
    }
    // A hand-made 4x4 8-bit page whose IFD is intact but whose strip lies past the end of the file.
    std::vector<std::uint8_t> tiny = {'I', 'I', 42, 0, 8, 0, 0, 0, 6, 0};
    auto entry = [&](std::uint16_t tag, std::uint16_t type, std::uint32_t value) {
        const std::uint8_t e[12] = {std::uint8_t(tag), std::uint8_t(tag >> 8), std::uint8_t(type), 0, 1, 0, 0, 0,
                                    std::uint8_t(value), std::uint8_t(value >> 8), std::uint8_t(value >> 16), 0};
        tiny.insert(tiny.end(), e, e + 12);
    };
    entry(TIFFTAG_IMAGEWIDTH, TIFF_SHORT, 4);
    entry(TIFFTAG_IMAGELENGTH, TIFF_SHORT, 4);
    entry(TIFFTAG_BITSPERSAMPLE, TIFF_SHORT, 8);
    entry(TIFFTAG_STRIPOFFSETS, TIFF_LONG, 1000);
    entry(TIFFTAG_ROWSPERSTRIP, TIFF_SHORT, 4);
    entry(TIFFTAG_STRIPBYTECOUNTS, TIFF_LONG, 16);
    tiny.insert(tiny.end(), 4, 0);  // no next IFD
    std::ofstream(dir + "/strip.tif", std::ios::binary).write(reinterpret_cast<const char*>(tiny.data()), std::streamsize(tiny.size()));
    expectMentions(expectReadError(dir + "/strip.tif"), dir + "/strip.tif",
                   "page 0: truncated file: strip 0 ends at byte 1016 but the file has 86 bytes");
    std::ofstream(dir + "/header.tif", std::ios::binary).write("II*\0", 4);
    expectMentions(expectReadError(dir + "/header.tif"), dir + "/header.tif", "cannot open as TIFF");
}

TEST(TiffReader, PagesOfDifferentSizesOrTypesAreRejected)
{
    const std::string dir = tempDirectory();
    TiffSpec a, wider, bytes;
    wider.width = 40;
    bytes.bits = 8;
    const SampleValue value = [](int, int, int, int) { return 1.0; };
    writeTiff(dir + "/sizes.tif", {a, a, wider}, value);
    expectMentions(expectReadError(dir + "/sizes.tif"), dir + "/sizes.tif", "page 2 (40x23");
    writeTiff(dir + "/types.tif", {a, bytes}, value);
    expectMentions(expectReadError(dir + "/types.tif"), dir + "/types.tif", "differs from page 0");
    // Numbered slices of different sizes: the error names the odd file.
    writeTiff(dir + "/s1.tif", {a}, value);
    writeTiff(dir + "/s2.tif", {wider}, value);
    osgDB::ReaderWriter::ReadResult r = readStack(dir + "/s*.tif");
    EXPECT_FALSE(r.success());
    expectMentions(r.message(), dir + "/s2.tif", "differs from page 0");
}

TEST(TiffReader, ImageJCountsThatDoNotMatchThePagesAreRejected)
{
    const std::string dir = tempDirectory();
    TiffSpec spec;
    auto write = [&](const std::string& name, const std::string& description) {
        spec.description = description;
        writeTiff(dir + "/" + name, spec, 3);
        return expectReadError(dir + "/" + name);
    };
    expectMentions(write("images.tif", "ImageJ=1.54f\nimages=1000000\nslices=1000000\n"), dir + "/images.tif",
                   "images=1000000 (channels=1 slices=1000000 frames=1) but the file has 3 pages");
    expectMentions(write("product.tif", "ImageJ=1.54f\nimages=3\nchannels=4\nslices=5\n"), dir + "/product.tif",
                   "does not add up");
    expectMentions(write("huge.tif", "ImageJ=1.54f\nimages=3\nchannels=99999999999\n"), dir + "/huge.tif",
                   "channels=99999999999 is not a positive count");
    expectMentions(write("overflow.tif", "ImageJ=1.54f\nchannels=2000000000\nslices=2000000000\nframes=2000000000\n"),
                   dir + "/overflow.tif", "does not add up");
    expectMentions(write("spacing.tif", "ImageJ=1.54f\nimages=3\nspacing=-1\n"), dir + "/spacing.tif", "spacing=-1");
    spec.description = "<OME><Image><Pixels SizeX=\"37\" SizeY=\"23\" SizeZ=\"5\" DimensionOrder=\"XYZCT\"/></Image></OME>";
    writeTiff(dir + "/ome.tif", spec, 3);
    expectMentions(expectReadError(dir + "/ome.tif"), dir + "/ome.tif", "but the file has 3 pages");
}

TEST(TiffReader, UnsupportedSampleFormatsAndBitDepthsAreRejected)
{
    const std::string dir = tempDirectory();
    auto check = [&](const std::string& name, std::uint16_t bits, std::uint16_t format, const std::string& reason) {
        TiffSpec spec;
        spec.bits = bits;
        spec.sampleFormat = format;
        writeTiff(dir + "/" + name, spec, 2);
        expectMentions(expectReadError(dir + "/" + name), dir + "/" + name, reason);
    };
    check("complex.tif", 32, SAMPLEFORMAT_COMPLEXINT, "unsupported sample format 5 (complex integer)");
    check("double.tif", 64, SAMPLEFORMAT_IEEEFP, "unsupported bits per sample 64");
    check("twelve.tif", 12, SAMPLEFORMAT_UINT, "unsupported bits per sample 12");
    check("half.tif", 16, SAMPLEFORMAT_IEEEFP, "16-bit floating point");
    check("bits.tif", 1, SAMPLEFORMAT_UINT, "unsupported bits per sample 1");
}

TEST(TiffReader, UnreadablePathsAndEmptyFoldersAreNamed)
{
    const std::string dir = tempDirectory();
    expectMentions(expectReadError(dir + "/nope.tif"), dir + "/nope.tif", "no such file");
    std::ofstream(dir + "/garbage.tif") << "this is not a TIFF file at all";
    expectMentions(expectReadError(dir + "/garbage.tif"), dir + "/garbage.tif", "cannot open as TIFF");
    std::ofstream(dir + "/empty.tif");
    expectMentions(expectReadError(dir + "/empty.tif"), dir + "/empty.tif", "cannot open as TIFF");
    std::filesystem::create_directories(dir + "/none");
    osgDB::ReaderWriter::ReadResult r = readStack(dir + "/none");
    EXPECT_FALSE(r.success());
    expectMentions(r.message(), dir + "/none", "empty directory");
    r = readStack(dir + "/none/z*.tif");
    expectMentions(r.message(), dir + "/none/z*.tif", "no file matches");
    r = readStack(dir + "/missing");
    EXPECT_EQ(r.status(), osgDB::ReaderWriter::ReadResult::FILE_NOT_HANDLED) << "no extension, not a folder";
    r = readStack(dir + "/missing/s*.tif");
    expectMentions(r.message(), dir + "/missing/s*.tif", "cannot read directory");
}

TEST(TiffReader, ReportsProgressPerPageAndHonoursCancellation)
{
    TiffSpec spec;
    const std::string path = tempDirectory() + "/stack.tif";
    writeTiff(path, spec, 6);
    std::vector<double> seen;
    LoadProgress record = [&](double f) {
        seen.push_back(f);
        return true;
    };
    osg::ref_ptr<osgDB::Options> options = withLoadProgress(nullptr, &record);
    readVolumeFile(path, options.get());
    ASSERT_EQ(seen.size(), 6u);
    for (std::size_t i = 0; i < seen.size(); ++i) EXPECT_DOUBLE_EQ(seen[i], double(i + 1) / 6.0);

    int calls = 0;
    LoadProgress cancel = [&](double) { return ++calls < 2; };
    options = withLoadProgress(nullptr, &cancel);
    expectMentions(expectReadError(path, options.get()), path, "cancelled");
    EXPECT_EQ(calls, 2);
}

}  // namespace
}  // namespace volren::test
