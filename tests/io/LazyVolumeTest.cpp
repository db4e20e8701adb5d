// Volumes opened lazily (larger than RAM): LazyRawSource under the raw, NRRD and MetaImage
// readers and OmeZarrSource under the OME-Zarr reader. Level 0 against the closed formula the
// files were written from, coarser levels against independent loops of the mean reduction, the
// preview Volume's geometry, errors that name the file, and reads from several threads.
#include "TestData.h"

#include <volume_model/LazyRawSource.h>
#include <volume_model/LoadProgress.h>
#include <volume_model/MeanReduction.h>
#include <volume_model/OmeZarrSource.h>
#include <volume_model/ReadVolume.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <random>
#include <thread>

namespace volren::test {
namespace {

/// The closed formula every raw-style test file holds (uint16).
int formula(int x, int y, int z) { return x + 3 * y + 7 * z; }

/// The formula's voxels of `dims` as uint16 bytes, little or big endian.
std::string formulaBytes(const osg::Vec3i& dims, bool bigEndian = false)
{
    std::string bytes;
    bytes.reserve(std::size_t(dims.x()) * dims.y() * dims.z() * 2);
    for (int z = 0; z < dims.z(); ++z)
        for (int y = 0; y < dims.y(); ++y)
            for (int x = 0; x < dims.x(); ++x) {
                const unsigned v = unsigned(formula(x, y, z));
                const char lo = char(v & 0xff), hi = char(v >> 8);
                bytes += bigEndian ? hi : lo;
                bytes += bigEndian ? lo : hi;
            }
    return bytes;
}

std::string dimsWords(const osg::Vec3i& d, const char* sep)
{
    return std::to_string(d.x()) + sep + std::to_string(d.y()) + sep + std::to_string(d.z());
}

osg::ref_ptr<osgDB::Options> opts(const std::string& text) { return new osgDB::Options(text); }

/// Voxels [origin, origin + size) of `level` as stored values.
std::vector<double> readValues(const BrickSource& s, int level, const osg::Vec3i& origin, const osg::Vec3i& size)
{
    const std::size_t n = std::size_t(size.x()) * size.y() * size.z(), vb = voxelSize(s.type());
    std::vector<std::uint8_t> bytes(n * vb);
    s.read(level, origin, size, bytes.data());
    std::vector<float> f(n);
    storedToFloat(s.type(), bytes.data(), n, f.data());
    return std::vector<double>(f.begin(), f.end());
}

std::vector<double> readLevel(const BrickSource& s, int level) { return readValues(s, level, {0, 0, 0}, s.levelDims(level)); }

/// Level `level` of the formula volume of `dims` by its definition for power-of-two dims: the
/// mean of each 2^L cube of level 0, rounded to the nearest integer.
std::vector<double> cubeMeans(const osg::Vec3i& dims, int level)
{
    const int k = 1 << level;
    const osg::Vec3i d(std::max(1, dims.x() / k), std::max(1, dims.y() / k), std::max(1, dims.z() / k));
    const osg::Vec3i box(dims.x() / d.x(), dims.y() / d.y(), dims.z() / d.z());
    std::vector<double> out;
    for (int z = 0; z < d.z(); ++z)
        for (int y = 0; y < d.y(); ++y)
            for (int x = 0; x < d.x(); ++x) {
                double sum = 0;
                for (int c = 0; c < box.z(); ++c)
                    for (int b = 0; b < box.y(); ++b)
                        for (int a = 0; a < box.x(); ++a) sum += formula(x * box.x() + a, y * box.y() + b, z * box.z() + c);
                out.push_back(std::round(sum / (double(box.x()) * box.y() * box.z())));
            }
    return out;
}

/// The next level of a grid in double, written out directly: each output voxel the weighted
/// mean over the 3-D box [j r, (j+1) r) per axis (weights = overlap lengths), NaN left out.
std::vector<double> directNextLevel(const std::vector<double>& in, const osg::Vec3i& d)
{
    const osg::Vec3i o(std::max(1, d.x() / 2), std::max(1, d.y() / 2), std::max(1, d.z() / 2));
    const auto overlap = [](int i, int j, double r) { return std::max(0.0, std::min((j + 1) * r, i + 1.0) - std::max(j * r, double(i))); };
    std::vector<double> out;
    for (int k = 0; k < o.z(); ++k)
        for (int j = 0; j < o.y(); ++j)
            for (int i = 0; i < o.x(); ++i) {
                double sum = 0, weight = 0;
                for (int z = 0; z < d.z(); ++z)
                    for (int y = 0; y < d.y(); ++y)
                        for (int x = 0; x < d.x(); ++x) {
                            const double w = overlap(x, i, double(d.x()) / o.x()) * overlap(y, j, double(d.y()) / o.y()) *
                                             overlap(z, k, double(d.z()) / o.z());
                            const double v = in[(std::size_t(z) * d.y() + y) * d.x() + x];
                            if (w > 0 && !std::isnan(v)) {
                                sum += w * v;
                                weight += w;
                            }
                        }
                out.push_back(weight > 0 ? sum / weight : std::numeric_limits<double>::quiet_NaN());
            }
    return out;
}

std::vector<double> formulaLevel0(const osg::Vec3i& d)
{
    std::vector<double> v;
    for (int z = 0; z < d.z(); ++z)
        for (int y = 0; y < d.y(); ++y)
            for (int x = 0; x < d.x(); ++x) v.push_back(formula(x, y, z));
    return v;
}

/// The sub-box [origin, origin + size) of a whole level of dims `d`.
std::vector<double> subBox(const std::vector<double>& all, const osg::Vec3i& d, const osg::Vec3i& origin, const osg::Vec3i& size)
{
    std::vector<double> out;
    for (int z = origin.z(); z < origin.z() + size.z(); ++z)
        for (int y = origin.y(); y < origin.y() + size.y(); ++y)
            for (int x = origin.x(); x < origin.x() + size.x(); ++x) out.push_back(all[(std::size_t(z) * d.y() + y) * d.x() + x]);
    return out;
}

/// A random region inside `d`.
void randomRegion(std::mt19937& rng, const osg::Vec3i& d, osg::Vec3i& origin, osg::Vec3i& size)
{
    for (int a = 0; a < 3; ++a) {
        origin[a] = std::uniform_int_distribution<int>(0, d[a] - 1)(rng);
        size[a] = std::uniform_int_distribution<int>(1, d[a] - origin[a])(rng);
    }
}

/// A raw file of the formula after `header` bytes of junk; its LazyRawSource layout.
LazyRawSource::Layout writeRawFile(const std::string& path, const osg::Vec3i& dims, std::size_t header = 0, bool bigEndian = false)
{
    writeFile(path, std::string(header, 'h') + formulaBytes(dims, bigEndian));
    LazyRawSource::Layout layout;
    layout.path = path;
    layout.offset = header;
    layout.dims = dims;
    layout.type = VoxelType::UInt16;
    layout.bigEndian = bigEndian;
    return layout;
}

TEST(MeanReduction, LevelDimsFollowTheMipRuleDownToOneVoxel)
{
    EXPECT_EQ(meanLevelDims({37, 20, 9}, 1), osg::Vec3i(18, 10, 4));
    EXPECT_EQ(meanLevelDims({37, 20, 9}, 4), osg::Vec3i(2, 1, 1));
    EXPECT_EQ(meanLevelCount({37, 20, 9}), 6);
    EXPECT_EQ(meanLevelCount({64, 32, 16}), 7);
    EXPECT_EQ(meanLevelCount({1, 1, 1}), 1);
}

TEST(MeanReduction, NextLevelOfAnOddFloatGridMatchesADirectLoop)
{
    const osg::Vec3i d(7, 5, 3);
    std::vector<float> in;
    for (int i = 0; i < d.x() * d.y() * d.z(); ++i) in.push_back(float(std::sin(i * 0.7) * 100.0));
    const std::vector<float> next = meanNextLevel(in, d);
    const std::vector<double> expected = directNextLevel(std::vector<double>(in.begin(), in.end()), d);
    ASSERT_EQ(next.size(), expected.size());
    for (std::size_t i = 0; i < next.size(); ++i) EXPECT_NEAR(next[i], expected[i], 1e-4) << i;
}

TEST(MeanReduction, NaNIsLeftOutPerAxisAndAllNaNStaysNaN)
{
    const float nan = std::numeric_limits<float>::quiet_NaN();
    // 2x2x2 -> 1: x first ((nan, 2) -> 2, (4, 6) -> 5, (nan, nan) -> nan, (8, 10) -> 9), then y
    // ((2, 5) -> 3.5, (nan, 9) -> 9), then z ((3.5, 9) -> 6.25).
    EXPECT_EQ(meanNextLevel({nan, 2, 4, 6, nan, nan, 8, 10}, {2, 2, 2}), std::vector<float>{6.25f});
    const std::vector<float> allNaN = meanNextLevel({nan, nan, nan, nan, nan, nan, nan, nan}, {2, 2, 2});
    ASSERT_EQ(allNaN.size(), 1u);
    EXPECT_TRUE(std::isnan(allNaN[0]));
    // 3 -> 1 along x: weights 1 each.
    EXPECT_EQ(meanNextLevel({1, nan, 4}, {3, 1, 1}), std::vector<float>{2.5f});
}

TEST(LazyRawSource, LevelZeroRegionsEqualTheFormula)
{
    const std::string dir = tempDirectory();
    for (const osg::Vec3i& dims : {osg::Vec3i(37, 20, 9), osg::Vec3i(64, 32, 16)}) {
        SCOPED_TRACE(dimsWords(dims, "x"));
        osg::ref_ptr<LazyRawSource> source = new LazyRawSource(writeRawFile(dir + "/v.raw", dims, 123), 1);
        EXPECT_EQ(source->levelCount(), meanLevelCount(dims));
        EXPECT_EQ(source->previewLevel(), source->levelCount() - 1);
        const std::vector<double> all = formulaLevel0(dims);
        EXPECT_EQ(readLevel(*source, 0), all);
        std::mt19937 rng(7);
        for (int i = 0; i < 40; ++i) {
            osg::Vec3i origin, size;
            randomRegion(rng, dims, origin, size);
            EXPECT_EQ(readValues(*source, 0, origin, size), subBox(all, dims, origin, size));
        }
        EXPECT_THROW(readValues(*source, 0, {1, 0, 0}, dims), std::invalid_argument);
    }
}

TEST(LazyRawSource, PowerOfTwoLevelsAreMeansOfCubesInMemoryOrOnDemand)
{
    const std::string dir = tempDirectory();
    const osg::Vec3i dims(64, 32, 16);
    const LazyRawSource::Layout layout = writeRawFile(dir + "/v.raw", dims);
    // Preview budgets that keep every level, levels 3.. (1 and 2 on demand), and level 0 in memory.
    for (const std::uint64_t budget : {std::uint64_t(1), std::uint64_t(8 * 4 * 2 * 2), std::uint64_t(1) << 30}) {
        osg::ref_ptr<LazyRawSource> source = new LazyRawSource(layout, budget);
        SCOPED_TRACE("preview level " + std::to_string(source->previewLevel()));
        std::size_t resident = 0;
        for (int l = 0; l < source->levelCount(); ++l) {
            EXPECT_EQ(readLevel(*source, l), cubeMeans(dims, l)) << "level " << l;
            if (l >= source->previewLevel()) resident += std::size_t(source->levelDims(l).x()) * source->levelDims(l).y() * source->levelDims(l).z() * 2;
        }
        EXPECT_EQ(source->residentBytes(), resident);
    }
    EXPECT_EQ(osg::ref_ptr<LazyRawSource>(new LazyRawSource(layout, 8 * 4 * 2 * 2))->previewLevel(), 3);
}

TEST(LazyRawSource, OddDimsLevelsFollowTheOverlapWeightedMeanAndRegionsAgree)
{
    const std::string dir = tempDirectory();
    const osg::Vec3i dims(37, 20, 9);
    const LazyRawSource::Layout layout = writeRawFile(dir + "/v.raw", dims);
    // Every level streamed at opening and kept; or only the last kept, the others reduced on demand.
    osg::ref_ptr<LazyRawSource> streamed = new LazyRawSource(layout, std::uint64_t(1) << 30);
    osg::ref_ptr<LazyRawSource> onDemand = new LazyRawSource(layout, 1);
    ASSERT_EQ(streamed->previewLevel(), 0);
    ASSERT_EQ(onDemand->previewLevel(), onDemand->levelCount() - 1);
    std::vector<double> exact = formulaLevel0(dims);  // the chain in double, never rounded
    std::mt19937 rng(11);
    for (int l = 1; l < streamed->levelCount(); ++l) {
        SCOPED_TRACE("level " + std::to_string(l));
        exact = directNextLevel(exact, meanLevelDims(dims, l - 1));
        const std::vector<double> got = readLevel(*streamed, l);
        ASSERT_EQ(got.size(), exact.size());
        for (std::size_t i = 0; i < got.size(); ++i) EXPECT_LE(std::abs(got[i] - exact[i]), 0.5 + 1e-3) << i;
        // Levels reduced region by region from level 0 on demand equal the streamed ones exactly.
        const osg::Vec3i ld = streamed->levelDims(l);
        EXPECT_EQ(readLevel(*onDemand, l), got);
        for (int i = 0; i < 10; ++i) {
            osg::Vec3i origin, size;
            randomRegion(rng, ld, origin, size);
            EXPECT_EQ(readValues(*onDemand, l, origin, size), subBox(got, ld, origin, size));
        }
    }
}

TEST(LazyRawSource, TruncatedOrShrunkFilesAreErrorsNamingTheFile)
{
    const std::string dir = tempDirectory();
    const osg::Vec3i dims(37, 20, 9);
    LazyRawSource::Layout layout = writeRawFile(dir + "/short.raw", dims);
    writeFile(layout.path, formulaBytes(dims).substr(10));
    try {
        osg::ref_ptr<LazyRawSource> source = new LazyRawSource(layout);
        ADD_FAILURE() << "a short file opened";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find(layout.path + ": truncated"), std::string::npos) << e.what();
    }
    // Shrunk after opening: the read fails, naming the file.
    layout = writeRawFile(dir + "/shrinks.raw", dims);
    osg::ref_ptr<LazyRawSource> source = new LazyRawSource(layout, 1);
    std::filesystem::resize_file(layout.path, 100);
    try {
        readLevel(*source, 0);
        ADD_FAILURE() << "a read past the end succeeded";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find(layout.path + ": truncated"), std::string::npos) << e.what();
    }
    layout.path = dir + "/absent.raw";
    EXPECT_THROW(osg::ref_ptr<LazyRawSource>(new LazyRawSource(layout)), std::runtime_error);
}

TEST(LazyRawSource, ConcurrentReadsFromFourThreadsGiveTheSameBytes)
{
    const std::string dir = tempDirectory();
    const osg::Vec3i dims(37, 20, 9);
    osg::ref_ptr<LazyRawSource> source = new LazyRawSource(writeRawFile(dir + "/v.raw", dims), 200);  // levels 0..2 from the file
    ASSERT_GT(source->previewLevel(), 1);
    std::vector<std::vector<double>> levels;
    for (int l = 0; l < source->levelCount(); ++l) levels.push_back(readLevel(*source, l));
    std::vector<int> wrong(4, 0);
    std::vector<std::thread> threads;
    for (int t = 0; t < 4; ++t)
        threads.emplace_back([&, t] {
            std::mt19937 rng{unsigned(100 + t)};
            for (int i = 0; i < 200; ++i) {
                const int l = i % source->levelCount();
                osg::Vec3i origin, size;
                randomRegion(rng, source->levelDims(l), origin, size);
                if (readValues(*source, l, origin, size) != subBox(levels[std::size_t(l)], source->levelDims(l), origin, size)) ++wrong[std::size_t(t)];
            }
        });
    for (std::thread& t : threads) t.join();
    EXPECT_EQ(wrong, std::vector<int>(4, 0));
}

/// The three raw-style formats, each a file of the formula with spacing 0.5, 1, 2.
enum class Format { Raw, Nrrd, MetaImage };

struct Written
{
    std::string path;
    std::string options;  ///< the layout options .raw needs
};

Written writeFormat(Format format, const std::string& dir, const osg::Vec3i& dims, bool bigEndian = false)
{
    const std::string bytes = formulaBytes(dims, bigEndian);
    switch (format) {
    case Format::Raw:
        writeFile(dir + "/v.raw", bytes);
        return {dir + "/v.raw", "dims=" + dimsWords(dims, ",") + " type=uint16 spacing=0.5,1,2" + (bigEndian ? " endian=big" : "")};
    case Format::Nrrd:
        writeFile(dir + "/v.nrrd", "NRRD0004\ntype: ushort\ndimension: 3\nsizes: " + dimsWords(dims, " ") +
                                       "\nspacings: 0.5 1 2\nendian: " + (bigEndian ? "big" : "little") + "\nencoding: raw\n\n" + bytes);
        return {dir + "/v.nrrd", ""};
    case Format::MetaImage:
        writeFile(dir + "/v.mha", "ObjectType = Image\nNDims = 3\nDimSize = " + dimsWords(dims, " ") +
                                      "\nElementSpacing = 0.5 1 2\nElementType = MET_USHORT\nElementByteOrderMSB = " +
                                      (bigEndian ? "True" : "False") + "\nElementDataFile = LOCAL\n" + bytes);
        return {dir + "/v.mha", ""};
    }
    return {};
}

class LazyReaders : public testing::TestWithParam<Format>
{
};

TEST_P(LazyReaders, OptionLazyGivesThePreviewLevelWithTheFullBox)
{
    const std::string dir = tempDirectory();
    const osg::Vec3i dims(64, 32, 16);
    const Written file = writeFormat(GetParam(), dir, dims);
    // `lazy` with room for level 0 in the preview: the whole volume, the source attached.
    osg::ref_ptr<Volume> whole = readVolumeFile(file.path, opts(file.options + " lazy").get());
    ASSERT_TRUE(whole->fullResolution());
    EXPECT_EQ(whole->fullResolutionLevel(), 0);
    EXPECT_EQ(whole->dims(), dims);
    EXPECT_EQ(whole->spacing(), osg::Vec3d(0.5, 1, 2));
    EXPECT_EQ(readLevel(*whole->fullResolution(), 0), formulaLevel0(dims));

    // A RAM budget of 0.05 MiB (under the 64 KiB payload) opens lazily without `lazy`; the
    // preview budget is 1/8 of it (6553 bytes): level 2, 16x8x4.
    osg::ref_ptr<Volume> v = readVolumeFile(file.path, opts(file.options + " ramBudgetMB=0.05").get());
    const BrickSource* source = v->fullResolution();
    ASSERT_TRUE(source);
    EXPECT_EQ(v->fullResolutionLevel(), 2);
    EXPECT_EQ(v->fullDims(), dims);
    EXPECT_EQ(v->dims(), osg::Vec3i(16, 8, 4));
    EXPECT_EQ(v->spacing(), osg::Vec3d(2, 4, 8));
    EXPECT_EQ(v->worldSize(), osg::Vec3d(32, 32, 32));
    EXPECT_EQ(source->spacing(), osg::Vec3d(0.5, 1, 2));
    EXPECT_EQ(v->sourceFile, file.path);
    std::vector<double> preview;
    for (std::size_t i = 0; i < v->voxelCount(); ++i) preview.push_back(v->storedValue(i));
    EXPECT_EQ(preview, cubeMeans(dims, 2));
    for (int l = 0; l < source->levelCount(); ++l) EXPECT_EQ(readLevel(*source, l), cubeMeans(dims, l)) << "level " << l;
    EXPECT_EQ(source->residentBytes(), std::size_t(16 * 8 * 4 + 8 * 4 * 2 + 4 * 2 + 2 + 1) * 2);

    // ramBudgetMB=0 opens everything lazily, the preview is the single voxel of the last level.
    osg::ref_ptr<Volume> tiny = readVolumeFile(file.path, opts(file.options + " ramBudgetMB=0").get());
    ASSERT_TRUE(tiny->fullResolution());
    EXPECT_EQ(tiny->dims(), osg::Vec3i(1, 1, 1));
    EXPECT_EQ(tiny->worldSize(), osg::Vec3d(32, 32, 32));

    // Under the budget and without `lazy`: read whole as before.
    osg::ref_ptr<Volume> eager = readVolumeFile(file.path, opts(file.options + " ramBudgetMB=1").get());
    EXPECT_FALSE(eager->fullResolution());
    EXPECT_EQ(eager->dims(), dims);
    EXPECT_EQ(eager->fullDims(), dims);
}

TEST_P(LazyReaders, BigEndianVoxelsAreSwappedAndOddDimsRead)
{
    const std::string dir = tempDirectory();
    const osg::Vec3i dims(37, 20, 9);
    const Written file = writeFormat(GetParam(), dir, dims, true);
    osg::ref_ptr<Volume> v = readVolumeFile(file.path, opts(file.options + " lazy").get());
    ASSERT_TRUE(v->fullResolution());
    const std::vector<double> all = formulaLevel0(dims);
    EXPECT_EQ(readLevel(*v->fullResolution(), 0), all);
    EXPECT_EQ(readValues(*v->fullResolution(), 0, {3, 5, 2}, {30, 1, 7}), subBox(all, dims, {3, 5, 2}, {30, 1, 7}));
    // Level 1 equals the mean of the whole-read volume's voxels (meanNextLevel, the renderer's rule).
    std::vector<float> level0(all.begin(), all.end());
    const std::vector<float> next = meanNextLevel(level0, dims);
    std::vector<std::uint8_t> stored(next.size() * 2);
    floatToStored(VoxelType::UInt16, next.data(), next.size(), stored.data());
    std::vector<std::uint8_t> got(stored.size());
    v->fullResolution()->read(1, {0, 0, 0}, meanLevelDims(dims, 1), got.data());
    EXPECT_EQ(got, stored);
}

TEST_P(LazyReaders, TruncatedPayloadIsAnErrorNamingTheFile)
{
    const std::string dir = tempDirectory();
    const Written file = writeFormat(GetParam(), dir, {37, 20, 9});
    std::filesystem::resize_file(file.path, std::filesystem::file_size(file.path) - 10);
    const std::string why = expectReadError(file.path, opts(file.options + " lazy").get());
    EXPECT_NE(why.find(file.path), std::string::npos) << why;
    EXPECT_NE(why.find("truncated"), std::string::npos) << why;
}

TEST_P(LazyReaders, OpeningReportsProgressAndCanBeCancelled)
{
    const std::string dir = tempDirectory();
    const Written file = writeFormat(GetParam(), dir, {64, 32, 16});
    std::vector<double> fractions;
    const LoadProgress record = [&](double f) {
        fractions.push_back(f);
        return true;
    };
    readVolumeFile(file.path, withLoadProgress(opts(file.options + " lazy").get(), &record).get());
    ASSERT_FALSE(fractions.empty());
    EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));
    EXPECT_EQ(fractions.back(), 1.0);
    const LoadProgress cancel = [](double f) { return f < 0.5; };
    const std::string why = expectReadError(file.path, withLoadProgress(opts(file.options + " lazy").get(), &cancel).get());
    EXPECT_NE(why.find("cancelled"), std::string::npos) << why;
}

INSTANTIATE_TEST_SUITE_P(Formats, LazyReaders, testing::Values(Format::Raw, Format::Nrrd, Format::MetaImage),
                         [](const testing::TestParamInfo<Format>& info) {
                             return info.param == Format::Raw ? "Raw" : info.param == Format::Nrrd ? "Nrrd" : "MetaImage";
                         });

TEST(LazyReaders, CompressedOrMultiChannelPayloadsAreReadWhole)
{
    const std::string dir = tempDirectory();
    writeFile(dir + "/two.raw", formulaBytes({4, 4, 4}));
    osg::ref_ptr<Volume> channels = readVolumeFile(dir + "/two.raw", opts("dims=4,4,2 type=uint16 channels=2 lazy").get());
    EXPECT_FALSE(channels->fullResolution());
    EXPECT_EQ(channels->channels(), 2);
}

// ---- OME-Zarr ----

std::string zarrFixture(const std::string& name) { return std::string(VOLREN_SOURCE_DIR) + "/tests/io/data/omezarr/" + name; }

std::vector<double> valuesOf(const Volume& v)
{
    std::vector<double> out;
    for (std::size_t i = 0; i < v.voxelCount(); ++i) out.push_back(v.storedValue(i));
    return out;
}

/// Equal, NaN equal to NaN.
void expectSameValues(const std::vector<double>& got, const std::vector<double>& expected)
{
    ASSERT_EQ(got.size(), expected.size());
    for (std::size_t i = 0; i < got.size(); ++i)
        if (!(std::isnan(got[i]) && std::isnan(expected[i]))) {
            EXPECT_EQ(got[i], expected[i]) << i;
        }
}

TEST(LazyOmeZarr, FileLevelsEqualTheWholeReadersLevelsAndReducedLevelsContinue)
{
    const std::string path = zarrFixture("pyramid.ome.zarr");
    osg::ref_ptr<Volume> v = readVolumeFile(path, opts("lazy").get());
    const BrickSource* source = v->fullResolution();
    ASSERT_TRUE(source);
    // File levels 10x8x6 and 5x4x3, then the reductions of 5x4x3: 2x2x1, 1x1x1.
    ASSERT_EQ(source->levelCount(), 4);
    EXPECT_EQ(source->levelDims(1), osg::Vec3i(5, 4, 3));
    EXPECT_EQ(source->levelDims(2), osg::Vec3i(2, 2, 1));
    EXPECT_EQ(source->levelDims(3), osg::Vec3i(1, 1, 1));
    EXPECT_EQ(v->fullResolutionLevel(), 0);
    EXPECT_EQ(v->dims(), osg::Vec3i(10, 8, 6));
    EXPECT_EQ(v->spacing(), osg::Vec3d(0.25, 0.5, 2.0));
    for (int l = 0; l < 2; ++l) {
        osg::ref_ptr<Volume> whole = readVolumeFile(path, opts("level=" + std::to_string(l)).get());
        EXPECT_FALSE(whole->fullResolution());
        EXPECT_EQ(readLevel(*source, l), valuesOf(*whole)) << "level " << l;
        EXPECT_EQ(readValues(*source, l, {1, 1, 1}, whole->dims() - osg::Vec3i(2, 2, 2)),
                  subBox(valuesOf(*whole), whole->dims(), {1, 1, 1}, whole->dims() - osg::Vec3i(2, 2, 2)));
    }
    osg::ref_ptr<Volume> level1 = readVolumeFile(path, opts("level=1").get());
    const std::vector<double> l1 = valuesOf(*level1);
    const std::vector<float> reduced = meanNextLevel(std::vector<float>(l1.begin(), l1.end()), {5, 4, 3});
    std::vector<double> expected;
    for (float f : reduced) expected.push_back(std::round(f));
    EXPECT_EQ(readLevel(*source, 2), expected);

    // ramBudgetMB=0: lazy without the option, the preview the last level, the box level 0's.
    osg::ref_ptr<Volume> tiny = readVolumeFile(path, opts("ramBudgetMB=0").get());
    ASSERT_TRUE(tiny->fullResolution());
    EXPECT_EQ(tiny->fullResolutionLevel(), 3);
    EXPECT_EQ(tiny->dims(), osg::Vec3i(1, 1, 1));
    EXPECT_EQ(tiny->worldSize(), osg::Vec3d(2.5, 4, 12));
    // An explicit level reads that level whole.
    EXPECT_FALSE(readVolumeFile(path, opts("ramBudgetMB=0 level=1").get())->fullResolution());
}

TEST(LazyOmeZarr, ChunkedCompressedAndNaNFixturesReadLikeTheWholeReader)
{
    for (const char* name : {"blosc_lz4.ome.zarr", "zlib_dot.ome.zarr", "forder.ome.zarr", "raw_bigendian.ome.zarr",
                             "f8_converted.ome.zarr", "float_nan_missing.ome.zarr"}) {
        SCOPED_TRACE(name);
        const std::string path = zarrFixture(name);
        osg::ref_ptr<Volume> whole = readVolumeFile(path);
        osg::ref_ptr<Volume> lazy = readVolumeFile(path, opts("lazy").get());
        ASSERT_TRUE(lazy->fullResolution());
        const BrickSource& source = *lazy->fullResolution();
        EXPECT_EQ(source.type(), whole->type());
        expectSameValues(readLevel(source, 0), valuesOf(*whole));
        std::mt19937 rng(3);
        for (int i = 0; i < 20; ++i) {
            osg::Vec3i origin, size;
            randomRegion(rng, whole->dims(), origin, size);
            expectSameValues(readValues(source, 0, origin, size), subBox(valuesOf(*whole), whole->dims(), origin, size));
        }
    }
}

TEST(LazyOmeZarr, ChannelsAndTimePointsKeepChannelZeroTimePointZero)
{
    const std::string path = zarrFixture("tczyx.ome.zarr");
    osg::ref_ptr<Volume> v = readVolumeFile(path, opts("lazy").get());
    ASSERT_TRUE(v->fullResolution());
    EXPECT_EQ(v->channels(), 1);
    EXPECT_EQ(v->frames(), 1);
    std::vector<double> expected;
    for (int z = 0; z < 3; ++z)
        for (int y = 0; y < 4; ++y)
            for (int x = 0; x < 5; ++x) expected.push_back(20 * z + 5 * y + x);
    EXPECT_EQ(valuesOf(*v), expected);
    EXPECT_EQ(readLevel(*v->fullResolution(), 0), expected);
    // Another channel and time point through the source directly.
    osg::ref_ptr<OmeZarrSource> c1t1 = new OmeZarrSource(path, 0, 1, 1, 1);
    EXPECT_EQ(readValues(*c1t1, 0, {0, 0, 2}, {5, 4, 1})[7], 1000 + 100 + 40 + 5 + 2);
    EXPECT_THROW(osg::ref_ptr<OmeZarrSource>(new OmeZarrSource(path, 0, 1, 2, 0)), std::runtime_error);
}

TEST(LazyOmeZarr, TheChunkCacheSavesDecodesAndConcurrentReadsAgree)
{
    const std::string path = zarrFixture("blosc_lz4.ome.zarr");  // 7x6x5 in chunks of 4x3x2
    osg::ref_ptr<OmeZarrSource> cached = new OmeZarrSource(path);
    osg::ref_ptr<OmeZarrSource> uncached = new OmeZarrSource(path, 0);
    const std::vector<double> all = readLevel(*uncached, 0);
    for (int i = 0; i < 3; ++i) {
        EXPECT_EQ(readLevel(*cached, 0), all);
        readLevel(*uncached, 0);
    }
    EXPECT_EQ(cached->chunkDecodes(), 2u * 2 * 3);  // each chunk decoded once
    EXPECT_EQ(uncached->chunkDecodes(), 4u * 2 * 2 * 3);
    EXPECT_GT(cached->residentBytes(), uncached->residentBytes());

    osg::ref_ptr<OmeZarrSource> small = new OmeZarrSource(path, 3 * 4 * 3 * 2 * 2);  // room for 3 chunks
    std::vector<int> wrong(4, 0);
    std::vector<std::thread> threads;
    for (int t = 0; t < 4; ++t)
        threads.emplace_back([&, t] {
            std::mt19937 rng{unsigned(t)};
            for (int i = 0; i < 300; ++i) {
                osg::Vec3i origin, size;
                randomRegion(rng, small->levelDims(0), origin, size);
                if (readValues(*small, 0, origin, size) != subBox(all, small->levelDims(0), origin, size)) ++wrong[std::size_t(t)];
            }
        });
    for (std::thread& t : threads) t.join();
    EXPECT_EQ(wrong, std::vector<int>(4, 0));
    EXPECT_LE(small->residentBytes(), std::size_t(3 * 4 * 3 * 2 * 2) + std::size_t(3 * 3 * 2 + 1 * 1 * 1) * 2);
}

}  // namespace
}  // namespace volren::test
