// OME-Zarr writer (osgdb_zarr writeObject): write -> read round trips, every pyramid level
// against a 2x2x2 mean computed here in integer arithmetic, the layout zarr readers expect,
// atomic replacement, progress, and (when Debian's python3-zarr is installed) zarr-python
// reading what was written.
#include "TestData.h"

#include <volume_model/LengthUnit.h>
#include <volume_model/LoadProgress.h>
#include <volume_model/OmeZarrImage.h>
#include <volume_model/ReadVolume.h>

#include <osgDB/Registry>
#include <osgDB/WriteFile>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sys/wait.h>

namespace volren::test {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

Json readJson(const std::string& file)
{
    std::ifstream in(file);
    return Json::parse(in);
}

/// A volume whose voxels differ in every position and reach negative values for signed types.
osg::ref_ptr<Volume> patternVolume(VoxelType type, const osg::Vec3i& dims, int channels, int frames)
{
    osg::ref_ptr<Volume> v = new Volume;
    v->allocate(type, dims, channels, frames);
    const bool isSigned = type == VoxelType::Int8 || type == VoxelType::Int16;
    for (std::size_t i = 0; i < v->totalVoxelCount(); ++i) {
        const int x = int(i * 37 % 101) - (isSigned ? 50 : 0);
        std::uint8_t* p = v->data() + i * voxelSize(type);
        switch (type) {
        case VoxelType::UInt8: *p = std::uint8_t(x); break;
        case VoxelType::Int8: *p = std::uint8_t(std::int8_t(x)); break;
        case VoxelType::UInt16: { const auto s = std::uint16_t(x * 600); std::memcpy(p, &s, 2); break; }
        case VoxelType::Int16: { const auto s = std::int16_t(x * 300 + 1); std::memcpy(p, &s, 2); break; }
        case VoxelType::Float32: { const float f = float(x) * 0.37f - 3.0f; std::memcpy(p, &f, 4); break; }
        }
    }
    v->setSpacing(osg::Vec3d(0.1, 0.7 / 3.0, 2.6));
    v->dirty();
    return v;
}

/// The expected next level of block (c, t) of `v`: mean of each 2x2x2 cell (fewer voxels at an
/// odd edge), integers rounded half away from zero in integer arithmetic; as doubles.
std::vector<double> expectedHalf(const std::vector<double>& in, const osg::Vec3i& d, bool integer, osg::Vec3i& h)
{
    h = osg::Vec3i((d.x() + 1) / 2, (d.y() + 1) / 2, (d.z() + 1) / 2);
    std::vector<double> out;
    for (int z = 0; z < h.z(); ++z)
        for (int y = 0; y < h.y(); ++y)
            for (int x = 0; x < h.x(); ++x) {
                long long sum = 0;
                double fsum = 0;
                int n = 0;
                for (int k = 2 * z; k <= 2 * z + 1 && k < d.z(); ++k)
                    for (int j = 2 * y; j <= 2 * y + 1 && j < d.y(); ++j)
                        for (int i = 2 * x; i <= 2 * x + 1 && i < d.x(); ++i) {
                            const double value = in[(std::size_t(k) * d.y() + j) * d.x() + i];
                            sum += (long long)(value);
                            fsum += value;
                            ++n;
                        }
                if (!integer) out.push_back(double(float(fsum / n)));
                else out.push_back(double(sum >= 0 ? (2 * sum + n) / (2 * n) : -((-2 * sum + n) / (2 * n))));
            }
    return out;
}

std::vector<double> blockValues(const Volume& v, int c, int t)
{
    std::vector<double> values(v.voxelCount());
    const std::size_t base = (std::size_t(t) * v.channels() + c) * v.voxelCount();
    for (std::size_t i = 0; i < values.size(); ++i) values[i] = v.storedValue(base + i);
    return values;
}

osg::ref_ptr<Volume> readLevel(const std::string& path, int level)
{
    osg::ref_ptr<osgDB::Options> options = new osgDB::Options("level=" + std::to_string(level));
    return readVolumeFile(path, options.get());
}

/// Checks every level of the pyramid at `path` against the mean of the level before, computed here.
void expectPyramid(const Volume& original, const std::string& path, int expectedLevels)
{
    const OmeZarrImage image(path);
    ASSERT_EQ(int(image.levelCount()), expectedLevels);
    const bool integer = original.type() != VoxelType::Float32;
    for (int t = 0; t < original.frames(); ++t)
        for (int c = 0; c < original.channels(); ++c) {
            std::vector<double> expected = blockValues(original, c, t);
            osg::Vec3i dims = original.dims();
            osg::Vec3d spacing = original.spacing();
            for (int l = 0; l < expectedLevels; ++l) {
                if (l > 0) {
                    osg::Vec3i half;
                    expected = expectedHalf(expected, dims, integer, half);
                    for (int a = 0; a < 3; ++a) spacing[a] *= dims[a] > 1 ? 2.0 : 1.0;
                    dims = half;
                }
                osg::ref_ptr<Volume> level = readLevel(path, l);
                ASSERT_EQ(level->dims(), dims) << "level " << l;
                EXPECT_EQ(level->type(), original.type());
                EXPECT_EQ(level->channels(), original.channels());
                EXPECT_EQ(level->frames(), original.frames());
                for (int a = 0; a < 3; ++a) EXPECT_DOUBLE_EQ(level->spacing()[a], spacing[a]) << "level " << l << " axis " << a;
                const std::vector<double> got = blockValues(*level, c, t);
                int wrong = 0;
                for (std::size_t i = 0; i < got.size(); ++i)
                    if (got[i] != expected[i] && wrong++ < 5)
                        ADD_FAILURE() << "level " << l << " block (" << c << ", " << t << ") voxel " << i << ": " << got[i] << ", expected "
                                      << expected[i];
                EXPECT_EQ(wrong, 0) << "level " << l;
            }
        }
}

TEST(OmeZarrWriter, SharedCtRoundTripsWithEqualVoxelsSpacingRescaleAndMeanLevels)
{
    VOLREN_REQUIRE_SHARED_DATA();
    registerPluginPath();
    const osg::ref_ptr<Volume> ct = readVolumeFile(sharedData("ct/CT_AVM.nii.gz"));  // 256x242x154 uint8, slope 2.2086
    const std::string path = tempDirectory() + "/avm.ome.zarr";
    ASSERT_TRUE(osgDB::writeObjectFile(*ct, path));
    const osg::ref_ptr<Volume> back = readVolumeFile(path);
    ASSERT_EQ(back->dims(), ct->dims());
    EXPECT_EQ(back->type(), ct->type());
    EXPECT_EQ(back->spacing(), ct->spacing());  // JSON numbers round-trip exactly
    EXPECT_EQ(back->rescaleSlope(), ct->rescaleSlope());
    EXPECT_EQ(back->rescaleIntercept(), ct->rescaleIntercept());
    std::string unit;  // NIfTI's xyzt_units mm, written under OME-NGFF's name
    EXPECT_TRUE(back->getUserValue(spacingUnitKey, unit));
    EXPECT_EQ(unit, "millimeter");
    ASSERT_EQ(back->byteSize(), ct->byteSize());
    EXPECT_EQ(std::memcmp(back->data(), ct->data(), ct->byteSize()), 0);
    // 256x242x154 -> 128x121x77 -> 64x61x39: three levels until every axis fits a 64 chunk.
    expectPyramid(*ct, path, 3);

    // The layout: blosc lz4 with byte shuffle, 64^3 chunks, "/" keys, z y x axes, scales.
    const Json zarray = readJson(path + "/0/.zarray");
    EXPECT_EQ(zarray["chunks"], Json({64, 64, 64}));
    EXPECT_EQ(zarray["shape"], Json({154, 242, 256}));
    EXPECT_EQ(zarray["dtype"], "|u1");
    EXPECT_EQ(zarray["compressor"]["id"], "blosc");
    EXPECT_EQ(zarray["compressor"]["cname"], "lz4");
    EXPECT_EQ(zarray["compressor"]["shuffle"], 1);
    EXPECT_EQ(zarray["dimension_separator"], "/");
    EXPECT_TRUE(fs::is_regular_file(path + "/0/2/3/3"));
    EXPECT_TRUE(fs::is_regular_file(path + "/.zgroup"));
    const Json attrs = readJson(path + "/.zattrs");
    const Json& m = attrs["multiscales"][0];
    EXPECT_EQ(m["version"], "0.4");
    EXPECT_EQ(m["axes"].size(), 3u);
    EXPECT_EQ(m["axes"][0]["name"], "z");
    EXPECT_EQ(m["datasets"].size(), 3u);
    EXPECT_EQ(m["datasets"][1]["coordinateTransformations"][0]["scale"][2], 2 * ct->spacing().x());
    EXPECT_DOUBLE_EQ(m["datasets"][1]["coordinateTransformations"][1]["translation"][2].get<double>(), 0.5 * ct->spacing().x());
}

struct PyramidCase
{
    VoxelType type;
    osg::Vec3i dims;
    int channels, frames;
    const char* options;
    int levels;
};

void PrintTo(const PyramidCase& p, std::ostream* os)
{
    *os << voxelTypeName(p.type) << " " << p.dims.x() << "x" << p.dims.y() << "x" << p.dims.z() << ", " << p.channels << " channels, "
        << p.frames << " frames, options \"" << p.options << "\"";
}

class OmeZarrPyramid : public ::testing::TestWithParam<PyramidCase>
{
};

TEST_P(OmeZarrPyramid, EveryLevelIsTheMeanOfTheOneBefore)
{
    registerPluginPath();
    const PyramidCase p = GetParam();
    osg::ref_ptr<Volume> original = patternVolume(p.type, p.dims, p.channels, p.frames);
    const std::string path = tempDirectory() + "/out.ome.zarr";
    osg::ref_ptr<osgDB::Options> options = new osgDB::Options(p.options);
    ASSERT_TRUE(osgDB::writeObjectFile(*original, path, options.get()));
    osg::ref_ptr<Volume> back = readVolumeFile(path);
    ASSERT_EQ(back->byteSize(), original->byteSize());
    EXPECT_EQ(std::memcmp(back->data(), original->data(), original->byteSize()), 0);
    EXPECT_EQ(back->spacing(), original->spacing());
    expectPyramid(*original, path, p.levels);
    // Axes: t and c only when there are several frames or channels.
    const Json axes = readJson(path + "/.zattrs")["multiscales"][0]["axes"];
    EXPECT_EQ(axes.size(), 3u + (p.channels > 1) + (p.frames > 1));
    if (p.channels > 1) {
        EXPECT_EQ(readJson(path + "/.zattrs")["omero"]["channels"].size(), std::size_t(p.channels));
    }
}

INSTANTIATE_TEST_SUITE_P(
    OmeZarrWriter, OmeZarrPyramid,
    ::testing::Values(PyramidCase{VoxelType::UInt8, {5, 4, 3}, 1, 1, "chunk=2", 3},
                      PyramidCase{VoxelType::Int8, {7, 3, 2}, 1, 1, "chunk=2 compression=zlib", 3},
                      PyramidCase{VoxelType::UInt16, {9, 6, 5}, 2, 1, "chunk=4 compression=gzip", 3},
                      PyramidCase{VoxelType::Int16, {6, 5, 1}, 1, 3, "chunk=2 compression=blosc-zstd", 3},
                      PyramidCase{VoxelType::Float32, {5, 7, 9}, 2, 2, "chunk=3 compression=none", 3},
                      PyramidCase{VoxelType::Int16, {33, 17, 9}, 1, 1, "", 1}),
    [](const ::testing::TestParamInfo<PyramidCase>& info) {
        const PyramidCase& p = info.param;
        return std::string(voxelTypeName(p.type)) + "_" + std::to_string(p.channels) + "ch_" + std::to_string(p.frames) + "t_" +
               std::to_string(info.index);
    });

TEST(OmeZarrWriter, ReplacesOnlyZarrFoldersAndAFailedWriteLeavesNothing)
{
    registerPluginPath();
    const std::string dir = tempDirectory();
    osg::ref_ptr<Volume> v = patternVolume(VoxelType::UInt8, {6, 6, 6}, 1, 1);
    // Over a plain file: refused, the file untouched.
    writeFile(dir + "/file.ome.zarr", "precious");
    osgDB::ReaderWriter::WriteResult result = osgDB::Registry::instance()->writeObject(*v, dir + "/file.ome.zarr", nullptr);
    EXPECT_FALSE(result.success());
    EXPECT_NE(result.message().find(dir + "/file.ome.zarr: exists and is not a zarr folder"), std::string::npos) << result.message();
    EXPECT_TRUE(fs::is_regular_file(dir + "/file.ome.zarr"));

    // Over an earlier pyramid: replaced (other dims now), no temporary folders left.
    const std::string path = dir + "/v.ome.zarr";
    ASSERT_TRUE(osgDB::writeObjectFile(*v, path));
    osg::ref_ptr<Volume> w = patternVolume(VoxelType::UInt8, {3, 4, 5}, 1, 1);
    ASSERT_TRUE(osgDB::writeObjectFile(*w, path));
    EXPECT_EQ(readVolumeFile(path)->dims(), osg::Vec3i(3, 4, 5));

    // Cancelled half-way: the old pyramid stays as it was; a new path does not appear.
    int calls = 0;
    const LoadProgress cancel = [&](double) { return ++calls < 2; };
    const osg::ref_ptr<osgDB::Options> chunk2 = new osgDB::Options("chunk=2");
    osg::ref_ptr<osgDB::Options> options = withLoadProgress(chunk2.get(), &cancel);
    result = osgDB::Registry::instance()->writeObject(*v, path, options.get());
    EXPECT_FALSE(result.success());
    EXPECT_NE(result.message().find("cancelled"), std::string::npos) << result.message();
    EXPECT_EQ(readVolumeFile(path)->dims(), osg::Vec3i(3, 4, 5));
    calls = 0;
    EXPECT_FALSE(osgDB::Registry::instance()->writeObject(*v, dir + "/new.ome.zarr", options.get()).success());
    EXPECT_FALSE(fs::exists(dir + "/new.ome.zarr"));
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir)) names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    EXPECT_EQ(names, (std::vector<std::string>{"file.ome.zarr", "v.ome.zarr"}));
}

TEST(OmeZarrWriter, ReportsProgressPerChunkAndRejectsBadOptions)
{
    registerPluginPath();
    const std::string dir = tempDirectory();
    osg::ref_ptr<Volume> v = patternVolume(VoxelType::UInt16, {8, 8, 8}, 1, 1);
    std::vector<double> seen;
    const LoadProgress record = [&](double f) {
        seen.push_back(f);
        return true;
    };
    // chunk=4: 8 chunks at level 0, 1 at level 1.
    const osg::ref_ptr<osgDB::Options> chunk4 = new osgDB::Options("chunk=4");
    ASSERT_TRUE(osgDB::writeObjectFile(*v, dir + "/p.ome.zarr", withLoadProgress(chunk4.get(), &record).get()));
    EXPECT_EQ(seen.size(), 9u);
    EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
    ASSERT_FALSE(seen.empty());
    EXPECT_EQ(seen.back(), 1.0);

    for (const char* bad : {"chunk=0", "chunk=abc", "chunk=5000", "compression=lzma"}) {
        osg::ref_ptr<osgDB::Options> options = new osgDB::Options(bad);
        const auto result = osgDB::Registry::instance()->writeObject(*v, dir + "/bad.ome.zarr", options.get());
        EXPECT_FALSE(result.success()) << bad;
        EXPECT_NE(result.message().find(std::string("option ") + bad), std::string::npos) << result.message();
        EXPECT_FALSE(fs::exists(dir + "/bad.ome.zarr")) << bad;
    }
}

/// Output of `command` (stdout and stderr) and its exit code.
std::pair<int, std::string> run(const std::string& command)
{
    std::string output;
    FILE* pipe = popen((command + " 2>&1").c_str(), "r");
    char buf[4096];
    std::size_t n;
    while ((n = fread(buf, 1, sizeof(buf), pipe)) > 0) output.append(buf, n);
    const int status = pclose(pipe);
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, output};
}

TEST(OmeZarrWriter, ZarrPythonReadsWhatTheWriterWrote)
{
    // Debian's python3-zarr, the independent reader (tools/setup.sh installs it). A pyenv python3
    // first on PATH would not see it, so Debian's interpreter is asked by its path. Missing, the
    // check fails: a skip here would pass on every machine without it.
    ASSERT_EQ(run("/usr/bin/python3 -c 'import zarr'").first, 0) << "python3-zarr is not installed (tools/setup.sh installs it)";
    registerPluginPath();
    const std::string path = tempDirectory() + "/py.ome.zarr";
    osg::ref_ptr<Volume> v = patternVolume(VoxelType::Int16, {9, 6, 5}, 2, 1);
    const osg::ref_ptr<osgDB::Options> chunk4 = new osgDB::Options("chunk=4");
    ASSERT_TRUE(osgDB::writeObjectFile(*v, path, chunk4.get()));
    // zarr-python prints, per level: shape, dtype and the sum and order-weighted sum of all values.
    const auto [code, output] = run("/usr/bin/python3 -c \"import zarr, numpy as np\n"
                                    "g = zarr.open_group('" + path + "', mode='r')\n"
                                    "for d in g.attrs['multiscales'][0]['datasets']:\n"
                                    "    a = g[d['path']][...].astype(np.int64)\n"
                                    "    w = np.arange(a.size, dtype=np.int64) % 251\n"
                                    "    print(d['path'], list(a.shape), g[d['path']].dtype, int(a.sum()), int((a.ravel() * w).sum()))\"");
    ASSERT_EQ(code, 0) << output;
    std::string expected;
    for (int l = 0; l < 3; ++l) {  // 9x6x5 -> 5x3x3 -> 3x2x2
        osg::ref_ptr<Volume> level = readLevel(path, l);
        long long sum = 0, weighted = 0;
        for (std::size_t i = 0; i < level->totalVoxelCount(); ++i) {
            sum += (long long)level->storedValue(i);
            weighted += (long long)(i % 251) * (long long)level->storedValue(i);
        }
        const osg::Vec3i& d = level->dims();
        expected += std::to_string(l) + " [2, " + std::to_string(d.z()) + ", " + std::to_string(d.y()) + ", " + std::to_string(d.x()) +
                    "] int16 " + std::to_string(sum) + " " + std::to_string(weighted) + "\n";
    }
    EXPECT_EQ(output, expected);
}

}  // namespace
}  // namespace volren::test
