// OME-Zarr 0.4 reader (osgdb_zarr) and the chunk API under it (ZarrArray, OmeZarrImage):
// fixtures written by zarr-python (tests/io/data/make_omezarr_fixtures.py) checked against the
// closed formulas that script used, and broken copies of them that must fail with the file
// and the reason.
#include "TestData.h"

#include <volume_model/ChannelDisplay.h>
#include <volume_model/LoadProgress.h>
#include <volume_model/OmeZarrImage.h>
#include <volume_model/ReadVolume.h>
#include <volume_model/ZarrArray.h>
#include <volume_model/ZarrCodec.h>

#include <osg/Matrixd>
#include <osgDB/ReadFile>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <zlib.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>

namespace volren::test {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

std::string fixture(const std::string& name)
{
    return std::string(VOLREN_SOURCE_DIR) + "/tests/io/data/omezarr/" + name;
}

/// A copy of fixture `name` in this test's temporary folder (to break it).
std::string copyFixture(const std::string& name)
{
    const std::string copy = tempDirectory() + "/" + name;
    fs::copy(fixture(name), copy, fs::copy_options::recursive);
    return copy;
}

std::string readText(const std::string& file)
{
    std::ifstream in(file, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), {});
}

/// Rewrites the JSON file `file` through `edit`.
void editJson(const std::string& file, const std::function<void(Json&)>& edit)
{
    Json j = Json::parse(readText(file));
    edit(j);
    writeFile(file, j.dump(2));
}

/// Stored value of voxel (x, y, z) of block (c, t).
double at(const Volume& v, int x, int y, int z, int c = 0, int t = 0)
{
    const osg::Vec3i& d = v.dims();
    const std::size_t block = std::size_t(t) * std::size_t(v.channels()) + std::size_t(c);
    return v.storedValue(block * v.voxelCount() + (std::size_t(z) * std::size_t(d.y()) + std::size_t(y)) * std::size_t(d.x()) + std::size_t(x));
}

/// Expects every voxel of block (c, t) of `v` to equal f(x, y, z); counts mismatches.
void expectFormula(const Volume& v, const std::function<double(int, int, int)>& f, int c = 0, int t = 0)
{
    int wrong = 0;
    const osg::Vec3i& d = v.dims();
    for (int z = 0; z < d.z(); ++z)
        for (int y = 0; y < d.y(); ++y)
            for (int x = 0; x < d.x(); ++x)
                if (at(v, x, y, z, c, t) != f(x, y, z) && wrong++ < 5)
                    ADD_FAILURE() << "voxel " << x << "," << y << "," << z << " (c " << c << ", t " << t << ") is " << at(v, x, y, z, c, t)
                                  << ", expected " << f(x, y, z);
    EXPECT_EQ(wrong, 0);
}

/// Expects readVolumeFile(path) to fail with a message naming `file` and containing `reason`.
void expectZarrError(const std::string& path, const std::string& file, const std::string& reason, const osgDB::Options* options = nullptr)
{
    const std::string why = expectReadError(path, options);
    EXPECT_NE(why.find(file), std::string::npos) << "message does not name " << file << ": " << why;
    EXPECT_NE(why.find(reason), std::string::npos) << "message lacks \"" << reason << "\": " << why;
}

std::string zlibBytes(const std::string& bytes)
{
    uLongf size = compressBound(uLong(bytes.size()));
    std::string out(size, '\0');
    compress2(reinterpret_cast<Bytef*>(&out[0]), &size, reinterpret_cast<const Bytef*>(bytes.data()), uLong(bytes.size()), 6);
    out.resize(size);
    return out;
}

TEST(OmeZarrReader, BloscLz4WithSlashSeparatorMatchesItsFormula)
{
    osg::ref_ptr<Volume> v = readVolumeFile(fixture("blosc_lz4.ome.zarr"));
    EXPECT_EQ(v->dims(), osg::Vec3i(7, 6, 5));
    EXPECT_EQ(v->type(), VoxelType::UInt16);
    EXPECT_EQ(v->channels(), 1);
    EXPECT_EQ(v->frames(), 1);
    EXPECT_EQ(v->sourceFile, fixture("blosc_lz4.ome.zarr"));
    expectFormula(*v, [](int x, int y, int z) { return x + 10 * y + 100 * z; });
}

TEST(OmeZarrReader, ZlibWithDotSeparatorKeepsSignedValues)
{
    osg::ref_ptr<Volume> v = readVolumeFile(fixture("zlib_dot.ome.zarr"));
    EXPECT_EQ(v->dims(), osg::Vec3i(6, 5, 4));
    EXPECT_EQ(v->type(), VoxelType::Int16);
    expectFormula(*v, [](int x, int y, int z) { return x - 2 * y + 3 * z - 20; });
}

TEST(OmeZarrReader, GzipUint8MatchesItsFormula)
{
    osg::ref_ptr<Volume> v = readVolumeFile(fixture("gzip_u1.ome.zarr"));
    EXPECT_EQ(v->dims(), osg::Vec3i(5, 4, 3));
    EXPECT_EQ(v->type(), VoxelType::UInt8);
    expectFormula(*v, [](int x, int y, int z) { return (x * 7 + y * 3 + z * 11) % 256; });
}

TEST(OmeZarrReader, UncompressedBigEndianIsSwapped)
{
    osg::ref_ptr<Volume> v = readVolumeFile(fixture("raw_bigendian.ome.zarr"));
    EXPECT_EQ(v->dims(), osg::Vec3i(5, 4, 3));
    EXPECT_EQ(v->type(), VoxelType::UInt16);
    expectFormula(*v, [](int x, int y, int z) { return 1000 * z + 37 * x + 5 * y + 256; });
}

TEST(OmeZarrReader, Float64AndInt32AreReadAsFloat32)
{
    osg::ref_ptr<Volume> f8 = readVolumeFile(fixture("f8_converted.ome.zarr"));
    EXPECT_EQ(f8->type(), VoxelType::Float32);
    EXPECT_EQ(f8->dims(), osg::Vec3i(4, 3, 3));
    expectFormula(*f8, [](int x, int y, int z) { return 0.5 * x + 0.25 * y - z; });  // exact in float
    osg::ref_ptr<Volume> i4 = readVolumeFile(fixture("i4_converted.ome.zarr"));
    EXPECT_EQ(i4->type(), VoxelType::Float32);
    EXPECT_EQ(i4->dims(), osg::Vec3i(4, 3, 2));
    expectFormula(*i4, [](int x, int y, int z) { return 100000 * z - 1000 * y + x; });
}

TEST(OmeZarrReader, FortranOrderChunksAreTransposed)
{
    osg::ref_ptr<Volume> v = readVolumeFile(fixture("forder.ome.zarr"));
    EXPECT_EQ(v->dims(), osg::Vec3i(6, 5, 4));
    EXPECT_EQ(v->type(), VoxelType::Int8);
    expectFormula(*v, [](int x, int y, int z) { return x - 2 * y + 3 * z - 5; });
}

TEST(OmeZarrReader, MissingChunkReadsAsTheNaNFillValue)
{
    osg::ref_ptr<Volume> v = readVolumeFile(fixture("float_nan_missing.ome.zarr"));
    EXPECT_EQ(v->type(), VoxelType::Float32);
    ASSERT_EQ(v->dims(), osg::Vec3i(4, 4, 4));
    int nan = 0, wrong = 0;
    for (int z = 0; z < 4; ++z)
        for (int y = 0; y < 4; ++y)
            for (int x = 0; x < 4; ++x) {
                const bool missing = z < 2 && y >= 2 && x < 2;  // the deleted chunk file 0/1/0
                const double value = at(*v, x, y, z);
                if (missing) nan += std::isnan(value) ? 1 : 0;
                else wrong += value == 0.25 * x - y + 0.5 * z ? 0 : 1;
            }
    EXPECT_EQ(nan, 8);
    EXPECT_EQ(wrong, 0);
    EXPECT_EQ(v->nonFiniteCount(), 8u);

    const ZarrArray array(fixture("float_nan_missing.ome.zarr/0"));
    EXPECT_TRUE(std::isnan(array.metadata().fillValue));
    bool missing = false;
    const std::vector<std::uint8_t> chunk = array.readChunk({0, 1, 0}, &missing);
    EXPECT_TRUE(missing);
    ASSERT_EQ(chunk.size(), 8u * 4u);
    float first;
    std::memcpy(&first, chunk.data(), 4);
    EXPECT_TRUE(std::isnan(first));
    EXPECT_EQ(array.missingChunks(), 1u);
    array.readChunk({0, 0, 0}, &missing);
    EXPECT_FALSE(missing);
}

TEST(ZarrArray, ReadsOneChunkOrOneRegionAtATime)
{
    const ZarrArray array(fixture("blosc_lz4.ome.zarr/0"));
    const ZarrArrayMetadata& m = array.metadata();
    EXPECT_EQ(m.shape, (std::vector<std::uint64_t>{5, 6, 7}));
    EXPECT_EQ(m.chunks, (std::vector<std::uint64_t>{2, 3, 4}));
    EXPECT_EQ(m.chunkGrid(), (std::vector<std::uint64_t>{3, 2, 2}));
    EXPECT_EQ(m.compressor.id, "blosc");
    EXPECT_EQ(m.compressor.cname, "lz4");
    EXPECT_EQ(m.compressor.shuffle, 1);
    EXPECT_EQ(m.separator, '/');
    EXPECT_EQ(array.chunkPath({2, 1, 0}), fixture("blosc_lz4.ome.zarr/0") + "/2/1/0");
    EXPECT_EQ(ZarrArray(fixture("zlib_dot.ome.zarr/0")).chunkPath({1, 0, 1}), fixture("zlib_dot.ome.zarr/0") + "/1.0.1");

    // Chunk (1, 1, 1): z 2-3, y 3-5, x 4-7 (x 7 is padding past the shape).
    const std::vector<std::uint8_t> chunk = array.readChunk({1, 1, 1});
    ASSERT_EQ(chunk.size(), 2u * 3u * 4u * 2u);
    int wrong = 0;
    for (int z = 0; z < 2; ++z)
        for (int y = 0; y < 3; ++y)
            for (int x = 0; x < 3; ++x) {
                std::uint16_t v;
                std::memcpy(&v, chunk.data() + 2 * ((z * 3 + y) * 4 + x), 2);
                wrong += v == (4 + x) + 10 * (3 + y) + 100 * (2 + z) ? 0 : 1;
            }
    EXPECT_EQ(wrong, 0);

    // A region across chunk borders: z 1-3, y 2-4, x 3-6.
    ZarrBox box{{1, 2, 3}, {4, 5, 7}};
    const std::vector<std::uint8_t> region = array.readRegion(box);
    ASSERT_EQ(region.size(), 3u * 3u * 4u * 2u);
    wrong = 0;
    for (int z = 0; z < 3; ++z)
        for (int y = 0; y < 3; ++y)
            for (int x = 0; x < 4; ++x) {
                std::uint16_t v;
                std::memcpy(&v, region.data() + 2 * ((z * 3 + y) * 4 + x), 2);
                wrong += v == (3 + x) + 10 * (2 + y) + 100 * (1 + z) ? 0 : 1;
            }
    EXPECT_EQ(wrong, 0);

    EXPECT_THROW(array.readChunk({3, 0, 0}), std::runtime_error);                  // off the grid
    EXPECT_THROW(array.readRegion(ZarrBox{{0, 0, 0}, {6, 1, 1}}), std::runtime_error);  // past the shape
}

TEST(OmeZarrReader, PyramidLevelsGiveSpacingUnitsAndPlacement)
{
    const std::string path = fixture("pyramid.ome.zarr");
    osg::ref_ptr<Volume> v0 = readVolumeFile(path);
    EXPECT_EQ(v0->dims(), osg::Vec3i(10, 8, 6));
    EXPECT_EQ(v0->spacing(), osg::Vec3d(0.25, 0.5, 2.0));
    expectFormula(*v0, [](int x, int y, int z) { return (x + 2 * y + 3 * z) % 256; });
    std::string unit;
    EXPECT_TRUE(v0->getUserValue("spacingUnit", unit));
    EXPECT_EQ(unit, "micrometer");
    int levels = 0;
    EXPECT_TRUE(v0->getUserValue("omeZarrLevels", levels));
    EXPECT_EQ(levels, 2);

    osg::ref_ptr<osgDB::Options> level1 = new osgDB::Options("level=1");
    osg::ref_ptr<Volume> v1 = readVolumeFile(path, level1.get());
    EXPECT_EQ(v1->dims(), osg::Vec3i(5, 4, 3));
    EXPECT_EQ(v1->spacing(), osg::Vec3d(0.5, 1.0, 4.0));
    expectFormula(*v1, [](int x, int y, int z) { return (2 * x + 4 * y + 6 * z) % 256; });  // level 0 at even indices
    osg::Matrixd toWorld;
    ASSERT_TRUE(v1->getUserValue("voxelToWorld", toWorld));
    const osg::Vec3d corner = osg::Vec3d(2, 3, 1) * toWorld;
    EXPECT_DOUBLE_EQ(corner.x(), 2 * 0.5 + 0.125);
    EXPECT_DOUBLE_EQ(corner.y(), 3 * 1.0 + 0.25);
    EXPECT_DOUBLE_EQ(corner.z(), 1 * 4.0 + 1.0);

    osg::ref_ptr<osgDB::Options> level2 = new osgDB::Options("level=2");
    expectZarrError(path, path, "level=2, but the image has levels 0 to 1", level2.get());
    osg::ref_ptr<osgDB::Options> bad = new osgDB::Options("level=x");
    expectZarrError(path, path, "option level=x", bad.get());

    const OmeZarrImage image(path);
    EXPECT_EQ(image.levelCount(), 2u);
    EXPECT_EQ(image.level(1).metadata().shape, (std::vector<std::uint64_t>{3, 4, 5}));
    EXPECT_EQ(image.spaceUnit(), "micrometer");
    EXPECT_EQ(image.origin(1)[2], 1.0);
}

TEST(OmeZarrReader, TczyxBecomesChannelAndTimeBlocksWithOmeroChannels)
{
    const std::string path = fixture("tczyx.ome.zarr");
    osg::ref_ptr<Volume> v = readVolumeFile(path);
    EXPECT_EQ(v->dims(), osg::Vec3i(5, 4, 3));
    EXPECT_EQ(v->channels(), 2);
    EXPECT_EQ(v->frames(), 2);
    EXPECT_EQ(v->type(), VoxelType::UInt16);
    for (int t = 0; t < 2; ++t)
        for (int c = 0; c < 2; ++c)
            expectFormula(*v, [c, t](int x, int y, int z) { return 1000 * t + 100 * c + 20 * z + 5 * y + x; }, c, t);
    EXPECT_EQ(v->spacing(), osg::Vec3d(0.25, 0.25, 1.5));
    double step = 0;
    std::string timeUnit;
    EXPECT_TRUE(v->getUserValue("timeStep", step));
    EXPECT_EQ(step, 0.5);
    EXPECT_TRUE(v->getUserValue("timeUnit", timeUnit));
    EXPECT_EQ(timeUnit, "second");

    const OmeZarrImage image(path);
    EXPECT_EQ(image.timeAxis(), 0);
    EXPECT_EQ(image.channelAxis(), 1);
    EXPECT_EQ(image.spaceAxis(0), 4);
    EXPECT_EQ(image.spaceAxis(2), 2);
    const std::vector<OmeroChannel>& channels = image.attributes().channels;
    ASSERT_EQ(channels.size(), 2u);
    EXPECT_EQ(channels[0].label, "DAPI");
    EXPECT_EQ(channels[0].color, "0000FF");
    EXPECT_EQ(channels[0].red, 0.f);
    EXPECT_EQ(channels[0].blue, 1.f);
    EXPECT_TRUE(channels[0].active);
    EXPECT_TRUE(channels[0].hasWindow);
    EXPECT_EQ(channels[0].windowMax, 4095.0);
    EXPECT_EQ(channels[0].windowStart, 10.0);
    // The volume carries them as display hints (windows in data values), and its default shows them.
    ASSERT_EQ(v->channelHints.size(), 2u);
    EXPECT_EQ(v->channelHints[0].name, "DAPI");
    EXPECT_EQ(v->channelHints[0].colours, std::vector<osg::Vec3f>{osg::Vec3f(0, 0, 1)});
    EXPECT_TRUE(v->channelHints[0].hasWindow);
    EXPECT_EQ(v->channelHints[0].low, 10.0);
    EXPECT_EQ(v->channelHints[0].high, 900.0);
    EXPECT_TRUE(v->channelHints[0].visible);
    EXPECT_EQ(v->channelHints[1].colours, std::vector<osg::Vec3f>{osg::Vec3f(0, 1, 0)});
    EXPECT_EQ(v->channelHints[1].low, 100.0);
    EXPECT_EQ(v->channelHints[1].high, 2000.0);
    EXPECT_FALSE(v->channelHints[1].visible);
    const std::vector<ChannelDisplay> shown = defaultChannelDisplays(*v);
    ASSERT_EQ(shown.size(), 2u);
    EXPECT_TRUE(shown[0].visible);
    EXPECT_FALSE(shown[1].visible) << "inactive in the file";
    EXPECT_EQ(shown[0].transferFunction->evaluate(900.0), osg::Vec4(0, 0, 1, float(defaultChannelOpacity)));
    EXPECT_EQ(shown[0].transferFunction->evaluate(10.0).a(), 0.0f);
    EXPECT_EQ(shown[1].transferFunction->evaluate(2000.0), osg::Vec4(0, 1, 0, float(defaultChannelOpacity)));
    EXPECT_EQ(channels[0].windowEnd, 900.0);
    EXPECT_EQ(channels[1].label, "GFP");
    EXPECT_EQ(channels[1].green, 1.f);
    EXPECT_FALSE(channels[1].active);
    EXPECT_EQ(channels[1].windowEnd, 2000.0);
}

TEST(OmeZarrReader, FoundThroughOsgDbWithATrailingSlashOrAsAnUnnamedFolderOrBareArray)
{
    registerPluginPath();
    const std::string path = fixture("gzip_u1.ome.zarr");
    osg::ref_ptr<osg::Object> object = osgDB::readRefObjectFile(path);
    ASSERT_NE(dynamic_cast<Volume*>(object.get()), nullptr);
    EXPECT_TRUE(osgDB::readRefNodeFile(path).valid()) << "a bare volume read as a node gets the default scene";
    EXPECT_TRUE(isVolumeFile(path));

    EXPECT_EQ(readVolumeFile(path + "/")->dims(), osg::Vec3i(5, 4, 3));
    const std::string unnamed = tempDirectory() + "/image";
    fs::copy(path, unnamed, fs::copy_options::recursive);
    EXPECT_EQ(readVolumeFile(unnamed)->dims(), osg::Vec3i(5, 4, 3));
    osg::ref_ptr<Volume> bare = readVolumeFile(path + "/0");  // the array itself: axes z y x
    EXPECT_EQ(bare->dims(), osg::Vec3i(5, 4, 3));
    expectFormula(*bare, [](int x, int y, int z) { return (x * 7 + y * 3 + z * 11) % 256; });
}

TEST(OmeZarrReader, ReportsProgressPerChunkAndCanBeCancelled)
{
    const std::string path = fixture("blosc_lz4.ome.zarr");  // 12 chunks
    std::vector<double> seen;
    const LoadProgress record = [&](double f) {
        seen.push_back(f);
        return true;
    };
    readVolumeFile(path, withLoadProgress(nullptr, &record).get());
    EXPECT_EQ(seen.size(), 12u);
    EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
    ASSERT_FALSE(seen.empty());
    EXPECT_EQ(seen.back(), 1.0);

    int calls = 0;
    const LoadProgress cancel = [&](double) { return ++calls < 3; };
    expectZarrError(path, path, "cancelled", withLoadProgress(nullptr, &cancel).get());
    EXPECT_EQ(calls, 3);
}

TEST(OmeZarrReader, LevelOverTheVoxelLimitSuggestsACoarserLevel)
{
    // Metadata only (every chunk missing): 4096^3 voxels at level 0, 2048^3 at level 1.
    const std::string path = tempDirectory() + "/huge.ome.zarr";
    for (const char* level : {"0", "1"}) fs::create_directories(path + "/" + level);
    writeFile(path + "/.zgroup", "{\"zarr_format\": 2}");
    const auto zarray = [](int n) {
        return "{\"zarr_format\": 2, \"shape\": [" + std::to_string(n) + ", " + std::to_string(n) + ", " + std::to_string(n) +
               "], \"chunks\": [64, 64, 64], \"dtype\": \"|u1\", \"compressor\": null, \"fill_value\": 0, \"order\": \"C\", "
               "\"filters\": null}";
    };
    writeFile(path + "/0/.zarray", zarray(4096));
    writeFile(path + "/1/.zarray", zarray(2048));
    writeFile(path + "/.zattrs",
              R"({"multiscales": [{"version": "0.4", "axes": [{"name": "z", "type": "space"}, {"name": "y", "type": "space"},
                 {"name": "x", "type": "space"}], "datasets": [
                 {"path": "0", "coordinateTransformations": [{"type": "scale", "scale": [1, 1, 1]}]},
                 {"path": "1", "coordinateTransformations": [{"type": "scale", "scale": [2, 2, 2]}]}]}]})");
    // A RAM budget over the 64 GiB of level 0, so that it is read whole (not opened lazily).
    osg::ref_ptr<osgDB::Options> whole = new osgDB::Options("ramBudgetMB=1000000");
    expectZarrError(path, path, "level 0 is 4096x4096x4096 voxels, over volren's limit of 2^34 voxels; read a coarser level with the option level=1",
                    whole.get());
}

// --- Bad input: every error names the file and the reason -----------------------------------

TEST(OmeZarrReaderErrors, TruncatedChunk)
{
    const std::string path = copyFixture("blosc_lz4.ome.zarr");
    const std::string chunk = path + "/0/1/0/1";
    const std::string bytes = readText(chunk);
    writeFile(chunk, bytes.substr(0, bytes.size() / 2));
    expectZarrError(path, chunk, "truncated blosc chunk");

    const std::string zlibPath = copyFixture("zlib_dot.ome.zarr");
    const std::string zlibChunk = zlibPath + "/0/0.1.0";
    const std::string zlibStream = readText(zlibChunk);
    writeFile(zlibChunk, zlibStream.substr(0, zlibStream.size() - 9));
    expectZarrError(zlibPath, zlibChunk, "truncated zlib chunk");

    const std::string rawPath = copyFixture("raw_bigendian.ome.zarr");
    const std::string rawChunk = rawPath + "/0/1.1.0";
    writeFile(rawChunk, readText(rawChunk).substr(3));
    expectZarrError(rawPath, rawChunk, "truncated chunk (37 bytes, the chunk shape and dtype of .zarray need 40 bytes)");
}

TEST(OmeZarrReaderErrors, ChunkOfTheWrongDecodedSize)
{
    // A zlib chunk of 10 bytes where .zarray's chunks 3x3x3 of <i2 need 54.
    const std::string path = copyFixture("zlib_dot.ome.zarr");
    writeFile(path + "/0/1.0.1", zlibBytes(std::string(10, '\1')));
    expectZarrError(path, path + "/0/1.0.1", "zlib chunk decodes to 10 bytes, but the chunk shape and dtype of .zarray need 54 bytes");
    writeFile(path + "/0/1.0.1", zlibBytes(std::string(60, '\1')));
    expectZarrError(path, path + "/0/1.0.1", "zlib chunk decodes to more than 54 bytes");

    // .zarray chunks that disagree with what the blosc chunks hold (2x3x4 of <u2 = 48 bytes).
    const std::string blosc = copyFixture("blosc_lz4.ome.zarr");
    editJson(blosc + "/0/.zarray", [](Json& j) { j["chunks"] = {2, 3, 3}; });
    expectZarrError(blosc, blosc + "/0/0/0/0", "blosc chunk decodes to 48 bytes, but the chunk shape and dtype of .zarray need 36 bytes");

    // A raw chunk with bytes to spare.
    const std::string raw = copyFixture("raw_bigendian.ome.zarr");
    writeFile(raw + "/0/0.0.0", readText(raw + "/0/0.0.0") + "xx");
    expectZarrError(raw, raw + "/0/0.0.0", "oversized chunk (42 bytes");
}

TEST(OmeZarrReaderErrors, CorruptChunkStreams)
{
    const std::string path = copyFixture("zlib_dot.ome.zarr");
    writeFile(path + "/0/0.0.0", "this is not a zlib stream at all");
    expectZarrError(path, path + "/0/0.0.0", "corrupt zlib chunk");
    // blosc stores chunks under 128 bytes as plain copies: a larger, compressed one to break.
    const std::string blosc = copyFixture("blosc_lz4.ome.zarr");
    editJson(blosc + "/0/.zarray", [](Json& j) { j["chunks"] = {5, 6, 7}; });
    std::vector<std::uint8_t> voxels(5 * 6 * 7 * 2);
    for (std::size_t i = 0; i < voxels.size(); ++i) voxels[i] = std::uint8_t(i % 2 ? 0 : i % 5);
    const std::vector<std::uint8_t> encoded = encodeZarrChunk(voxels.data(), voxels.size(), 2, ZarrCompressor{"blosc", "lz4", 5, 1, 0});
    std::string bytes(encoded.begin(), encoded.end());
    ASSERT_EQ(bytes[2] & 0x2, 0) << "blosc stored the chunk uncompressed";
    writeFile(blosc + "/0/0/0/0", bytes);
    EXPECT_EQ(readVolumeFile(blosc)->storedValue(2), 4.0);  // bytes 4 and 5: 4, 0 (little endian)
    for (std::size_t i = 16; i < bytes.size(); ++i) bytes[i] = char(0xff);
    writeFile(blosc + "/0/0/0/0", bytes);
    expectZarrError(blosc, blosc + "/0/0/0/0", "corrupt blosc chunk");
}

TEST(OmeZarrReaderErrors, UnknownCodecsFiltersAndDtypes)
{
    const std::string path = copyFixture("gzip_u1.ome.zarr");
    const std::string zarray = path + "/0/.zarray";
    const std::string original = readText(zarray);
    const auto expectEdit = [&](const std::function<void(Json&)>& edit, const std::string& reason) {
        writeFile(zarray, original);
        editJson(zarray, edit);
        expectZarrError(path, zarray, reason);
    };
    expectEdit([](Json& j) { j["compressor"] = {{"id", "lzma"}}; }, "unknown compressor \"lzma\"");
    expectEdit([](Json& j) { j["compressor"] = {{"id", "blosc"}, {"cname", "brotli"}, {"clevel", 5}, {"shuffle", 1}}; },
               "unknown blosc codec \"brotli\"");
    expectEdit([](Json& j) { j["filters"] = Json::array({{{"id", "delta"}, {"dtype", "<u2"}}}); }, "filters are not supported (filter \"delta\")");
    expectEdit([](Json& j) { j["dtype"] = "<c8"; }, "unknown dtype \"<c8\"");
    expectEdit([](Json& j) { j["dtype"] = "<f2"; }, "unknown dtype \"<f2\"");
    expectEdit([](Json& j) { j["dtype"] = "|u2"; }, "unknown dtype \"|u2\"");
    expectEdit([](Json& j) { j["dtype"] = Json::array({Json::array({"a", "<u1"})}); }, "structured dtype");
    expectEdit([](Json& j) { j["order"] = "K"; }, "order \"K\" is not \"C\" or \"F\"");
    expectEdit([](Json& j) { j["dimension_separator"] = "-"; }, "dimension_separator \"-\"");
    expectEdit([](Json& j) { j["fill_value"] = 300; }, "fill_value 300 is out of range for dtype |u1");
    expectEdit([](Json& j) { j["fill_value"] = "NaN"; }, "fill_value \"NaN\" for the integer dtype |u1");
    expectEdit([](Json& j) { j["zarr_format"] = 3; }, "zarr_format 3");
}

TEST(OmeZarrReaderErrors, AbsurdShapesOverflowOrExceedTheChunkLimit)
{
    const std::string path = copyFixture("gzip_u1.ome.zarr");
    const std::string zarray = path + "/0/.zarray";
    editJson(zarray, [](Json& j) { j["shape"] = {std::uint64_t(1) << 32, std::uint64_t(1) << 32, std::uint64_t(1) << 32}; });
    expectZarrError(path, zarray, "overflows (more than 2^64 elements)");
    editJson(zarray, [](Json& j) {
        j["shape"] = {3, 4, 5};
        j["chunks"] = {4096, 4096, 4096};
    });
    expectZarrError(path, zarray, "over volren's limit of 512 MiB per chunk");
    editJson(zarray, [](Json& j) { j["chunks"] = {1, 0, 1}; });
    expectZarrError(path, zarray, "has a zero extent");
    editJson(zarray, [](Json& j) { j["chunks"] = {1, -2, 1}; });
    expectZarrError(path, zarray, "not a non-negative whole number");
    editJson(zarray, [](Json& j) { j["chunks"] = {2, 2}; });
    expectZarrError(path, zarray, "have different numbers of dimensions");
    editJson(zarray, [](Json& j) {
        j["chunks"] = {2, 2, 2, 2};
        j["shape"] = {3, 4, 5, 6};
    });
    expectZarrError(path, zarray, "level 0 has 4 dimensions but the image has 3 axes");
}

TEST(OmeZarrReaderErrors, LevelsThatDisagree)
{
    const std::string path = copyFixture("pyramid.ome.zarr");
    const std::string level1 = path + "/1/.zarray";
    const std::string original = readText(level1);
    editJson(level1, [](Json& j) { j["dtype"] = "<u2"; });
    expectZarrError(path, level1, "level 1 has dtype <u2 but level 0 has |u1 (the levels disagree)");
    writeFile(level1, original);
    editJson(level1, [](Json& j) { j["shape"] = {3, 4, 11}; });
    expectZarrError(path, level1, "level 1 is 3x4x11 but level 0 is 6x8x10 (the levels disagree along axis \"x\"");

    const std::string tczyx = copyFixture("tczyx.ome.zarr");
    editJson(tczyx + "/.zattrs", [](Json& j) {
        Json level = j["multiscales"][0]["datasets"][0];
        level["path"] = "1";
        level["coordinateTransformations"][0]["scale"] = {0.5, 1.0, 3.0, 0.5, 0.5};
        j["multiscales"][0]["datasets"].push_back(level);
    });
    fs::create_directories(tczyx + "/1");
    writeFile(tczyx + "/1/.zarray", readText(tczyx + "/0/.zarray"));
    editJson(tczyx + "/1/.zarray", [](Json& j) { j["shape"] = {2, 3, 2, 2, 3}; });
    expectZarrError(tczyx, tczyx + "/1/.zarray", "time points and channels must match");
}

TEST(OmeZarrReaderErrors, MissingOrMalformedMetadata)
{
    const std::string path = copyFixture("pyramid.ome.zarr");
    fs::remove(path + "/1/.zarray");
    expectZarrError(path, path + "/1/.zarray", "no such file");

    const std::string malformed = copyFixture("gzip_u1.ome.zarr");
    writeFile(malformed + "/.zattrs", "{\"multiscales\": [");
    expectZarrError(malformed, malformed + "/.zattrs", "malformed JSON");
    writeFile(malformed + "/0/.zarray", "{\"shape\": [3, 4,");
    expectZarrError(malformed + "/0", malformed + "/0/.zarray", "malformed JSON");

    const std::string noAttrs = copyFixture("zlib_dot.ome.zarr");
    fs::remove(noAttrs + "/.zattrs");
    expectZarrError(noAttrs, noAttrs + "/.zattrs", "no such file (a zarr group without OME-Zarr metadata)");

    const std::string attrs = copyFixture("tczyx.ome.zarr");
    const std::string zattrs = attrs + "/.zattrs";
    const std::string original = readText(zattrs);
    const auto expectEdit = [&](const std::function<void(Json&)>& edit, const std::string& reason) {
        writeFile(zattrs, original);
        editJson(zattrs, edit);
        expectZarrError(attrs, zattrs, reason);
    };
    expectEdit([](Json& j) { j.erase("multiscales"); }, "no \"multiscales\"");
    expectEdit([](Json& j) { j["multiscales"][0]["version"] = "0.5"; }, "OME-Zarr version 0.5 is not supported");
    expectEdit([](Json& j) { j["multiscales"][0]["axes"][0]["name"] = "c"; }, "axis name \"c\" appears twice");
    expectEdit([](Json& j) { std::swap(j["multiscales"][0]["axes"][0], j["multiscales"][0]["axes"][4]); }, "is out of order");
    expectEdit([](Json& j) { j["multiscales"][0]["datasets"][0]["coordinateTransformations"][0]["scale"] = {1, 1, 1}; },
               "dataset 0 scale has 3 values for 5 axes");
    expectEdit([](Json& j) { j["multiscales"][0]["datasets"][0]["coordinateTransformations"][0]["scale"][4] = 0; },
               "not a positive number");
    expectEdit([](Json& j) { j["multiscales"][0]["datasets"][0]["path"] = "../../etc"; }, "is not a folder inside the image");
    expectEdit([](Json& j) { j["omero"]["channels"][0]["color"] = "blue"; }, "omero channel 0 color \"blue\" is not RRGGBB hex");

    const std::string v3 = copyFixture("gzip_u1.ome.zarr");
    writeFile(v3 + "/zarr.json", "{}");
    expectZarrError(v3, v3 + "/zarr.json", "zarr v3 (OME-Zarr 0.5) is not supported");
}

TEST(ZarrCodec, EncodesWhatItDecodesForEveryCompressor)
{
    std::vector<std::uint8_t> data(3000);
    for (std::size_t i = 0; i < data.size(); ++i) data[i] = std::uint8_t(i * 7 % 13);
    for (const ZarrCompressor& c : {ZarrCompressor{"", "", 0, 0, 0}, ZarrCompressor{"zlib", "", 6, 0, 0}, ZarrCompressor{"gzip", "", 6, 0, 0},
                                    ZarrCompressor{"blosc", "lz4", 5, 1, 0}, ZarrCompressor{"blosc", "zstd", 3, 2, 0},
                                    ZarrCompressor{"blosc", "blosclz", 9, 0, 0}}) {
        const std::vector<std::uint8_t> encoded = encodeZarrChunk(data.data(), data.size(), 2, c);
        if (!c.id.empty()) {
            EXPECT_LT(encoded.size(), data.size()) << c.id << " " << c.cname;
        }
        EXPECT_EQ(decodeZarrChunk(encoded.data(), encoded.size(), c, data.size(), "chunk"), data) << c.id << " " << c.cname;
        EXPECT_THROW(decodeZarrChunk(encoded.data(), encoded.size(), c, data.size() + 2, "chunk"), std::runtime_error) << c.id;
    }
}

}  // namespace
}  // namespace volren::test
