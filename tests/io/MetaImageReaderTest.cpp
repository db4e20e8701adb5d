// MetaImage reader: the shared dataset (MANIFEST values and an independent decode of the raw
// bytes), the .mha/.mhd variants, and bad files that must fail with the file name and reason.
#include "TestData.h"

#include <volume_model/LoadProgress.h>
#include <volume_model/ReadVolume.h>

#include <osgDB/ReadFile>
#include <gtest/gtest.h>
#include <zlib.h>

#include <cstring>
#include <filesystem>
#include <fstream>

namespace volren::test {
namespace {

/// A zlib stream (what MetaImage's CompressedData holds).
std::string zlibbed(const std::string& bytes)
{
    uLongf size = compressBound(uLong(bytes.size()));
    std::string out(size, '\0');
    compress2(reinterpret_cast<Bytef*>(&out[0]), &size, reinterpret_cast<const Bytef*>(bytes.data()), uLong(bytes.size()), 6);
    out.resize(size);
    return out;
}

std::string uint16Ramp(int n, int scale)
{
    std::string bytes;
    for (int i = 0; i < n; ++i) {
        const std::uint16_t v = std::uint16_t(i * scale);
        bytes.append(reinterpret_cast<const char*>(&v), 2);
    }
    return bytes;
}


const std::string header = "ObjectType = Image\nNDims = 3\nDimSize = 2 3 4\nElementSpacing = 0.5 0.25 3\nElementType = MET_USHORT\n";

TEST(MetaImageReader, ReadsHeadMRVolumeAsInTheManifest)
{
    VOLREN_REQUIRE_SHARED_DATA();
    const std::string path = sharedData("mri/HeadMRVolume.mhd");
    osg::ref_ptr<Volume> v = readVolumeFile(path);
    EXPECT_EQ(v->dims(), osg::Vec3i(48, 62, 42));
    EXPECT_EQ(v->type(), VoxelType::UInt8);
    EXPECT_EQ(v->channels(), 1);
    EXPECT_EQ(v->spacing(), osg::Vec3d(4, 4, 4));
    // Independent: python3 -c "import array; a=array.array('B', open('mri/HeadMRVolume.raw','rb').read());
    //   print(sum(a), min(a), max(a), sum((i%251)*x for i,x in enumerate(a)))"
    // (raw file sha256 714ff5b2db59d3867675d0f2419c24a71ed234985b39dc1ea83ee7d72110de4b, as in MANIFEST).
    double sum = 0, lo = 1e9, hi = -1e9, weighted = 0;
    for (std::size_t i = 0; i < v->voxelCount(); ++i) {
        const double x = v->storedValue(i);
        sum += x;
        lo = std::min(lo, x);
        hi = std::max(hi, x);
        weighted += double(i % 251) * x;
    }
    EXPECT_EQ(sum, 3058332.0);
    EXPECT_EQ(lo, 0.0);
    EXPECT_EQ(hi, 255.0);
    EXPECT_EQ(weighted, 381624975.0);

    registerPluginPath();
    osg::ref_ptr<osg::Object> object = osgDB::readRefObjectFile(path);
    ASSERT_NE(dynamic_cast<Volume*>(object.get()), nullptr) << "osgDB::readRefObjectFile did not give a volren::Volume";
    EXPECT_TRUE(osgDB::readRefNodeFile(path).valid());
}

TEST(MetaImageReader, ReadsLocalCompressedBigEndianListAndPatternVariants)
{
    const std::string dir = tempDirectory();
    const std::string ramp = uint16Ramp(24, 1000);
    std::string big = ramp;
    for (std::size_t i = 0; i < big.size(); i += 2) std::swap(big[i], big[i + 1]);
    const std::string packed = zlibbed(ramp);
    writeFile(dir + "/local.mha", header + "ElementByteOrderMSB = False\nElementDataFile = LOCAL\n" + ramp);
    writeFile(dir + "/msb.mha", header + "BinaryDataByteOrderMSB = True\nElementDataFile = LOCAL\n" + big);
    writeFile(dir + "/zip.mha", header + "CompressedData = True\nCompressedDataSize = " + std::to_string(packed.size()) +
                                    "\nElementDataFile = LOCAL\n" + packed);
    writeFile(dir + "/data.raw", ramp);
    writeFile(dir + "/plain.mhd", header + "ElementDataFile = data.raw\n");
    writeFile(dir + "/part1.raw", ramp.substr(0, 24));
    writeFile(dir + "/part2.raw", ramp.substr(24));
    writeFile(dir + "/list.mhd", header + "ElementDataFile = LIST\npart1.raw\npart2.raw\n");
    writeFile(dir + "/pattern.mhd", header + "ElementDataFile = part%d.raw 1 2 1\n");
    for (const char* name : {"/local.mha", "/msb.mha", "/zip.mha", "/plain.mhd", "/list.mhd", "/pattern.mhd"}) {
        osg::ref_ptr<Volume> v = readVolumeFile(dir + name);
        ASSERT_EQ(v->dims(), osg::Vec3i(2, 3, 4)) << name;
        EXPECT_EQ(v->type(), VoxelType::UInt16) << name;
        EXPECT_EQ(v->spacing(), osg::Vec3d(0.5, 0.25, 3)) << name;
        for (int i = 0; i < 24; ++i) ASSERT_EQ(v->value(std::size_t(i)), 1000.0 * i) << name << " " << i;
    }
}

TEST(MetaImageReader, ChannelsAreDeinterleavedAndElementSizeIsTheFallbackSpacing)
{
    const std::string dir = tempDirectory();
    std::string bytes;
    for (int i = 0; i < 8; ++i) bytes += {char(i), char(50 + i)};
    writeFile(dir + "/two.mha", "NDims = 3\nDimSize = 2 2 2\nElementSize = 1 2 3\nElementNumberOfChannels = 2\n"
                                "ElementType = MET_UCHAR_ARRAY\nElementDataFile = LOCAL\n" + bytes);
    osg::ref_ptr<Volume> v = readVolumeFile(dir + "/two.mha");
    EXPECT_EQ(v->channels(), 2);
    EXPECT_EQ(v->spacing(), osg::Vec3d(1, 2, 3));
    for (int i = 0; i < 8; ++i) {
        EXPECT_EQ(v->block(0)[i], i);
        EXPECT_EQ(v->block(1)[i], 50 + i);
    }
}

TEST(MetaImageReader, TruncatedPayloadIsRejected)
{
    expectRejected("short.mha", header + "ElementDataFile = LOCAL\n" + uint16Ramp(23, 1), "truncated");
    const std::string packed = zlibbed(uint16Ramp(24, 1));
    expectRejected("cut.mha", header + "CompressedData = True\nElementDataFile = LOCAL\n" + packed.substr(0, packed.size() / 2),
                   "truncated");
    expectRejected("cutsize.mha", header + "CompressedData = True\nCompressedDataSize = 1000\nElementDataFile = LOCAL\n" + packed,
                   "truncated");
}

TEST(MetaImageReader, HeaderSizeMismatchIsRejected)
{
    expectRejected("long.mha", header + "ElementDataFile = LOCAL\n" + uint16Ramp(25, 1), "size mismatch");
}

TEST(MetaImageReader, ZeroNegativeAndOverflowingSizesAreRejected)
{
    const std::string rest = "ElementType = MET_UCHAR\nElementDataFile = LOCAL\nx";
    expectRejected("zero.mha", "NDims = 3\nDimSize = 0 1 1\n" + rest, "dimensions must be positive");
    expectRejected("negative.mha", "NDims = 3\nDimSize = 1 -5 1\n" + rest, "dimensions must be positive");
    expectRejected("huge.mha", "NDims = 3\nDimSize = 2000000000 2000000000 2000000000\n" + rest, "exceeds the limit");
    expectRejected("count.mha", "NDims = 3\nDimSize = 1 1\n" + rest, "DimSize '1 1' must list 3 sizes");
}

TEST(MetaImageReader, UnknownElementTypeIsRejectedAndDoubleIsReadAsFloat)
{
    expectRejected("long.mha", "NDims = 3\nDimSize = 1 1 1\nElementType = MET_LONG_LONG\nElementDataFile = LOCAL\n12345678",
                   "ElementType 'MET_LONG_LONG' is not supported");
    const double value = 0.1;
    std::string bytes(8, '\0');
    std::memcpy(bytes.data(), &value, 8);
    const std::string dir = tempDirectory();
    writeFile(dir + "/double.mha", "NDims = 3\nDimSize = 1 1 1\nElementType = MET_DOUBLE\nElementDataFile = LOCAL\n" + bytes);
    osg::ref_ptr<Volume> v = readVolumeFile(dir + "/double.mha");
    ASSERT_TRUE(v);
    EXPECT_EQ(v->type(), VoxelType::Float32);
    EXPECT_EQ(v->value(std::size_t(0)), double(0.1f));
}

TEST(MetaImageReader, CorruptZlibStreamIsRejected)
{
    std::string packed = zlibbed(uint16Ramp(24, 7));
    for (std::size_t i = 2; i < packed.size(); ++i) packed[i] = char(0xff);
    expectRejected("corrupt.mha", header + "CompressedData = True\nElementDataFile = LOCAL\n" + packed, "corrupt compressed data");
}

TEST(MetaImageReader, MissingDetachedDataFileIsRejected)
{
    const std::string dir = tempDirectory();
    writeFile(dir + "/lost.mhd", header + "ElementDataFile = gone.raw\n");
    const std::string why = expectReadError(dir + "/lost.mhd");
    EXPECT_NE(why.find(dir + "/lost.mhd"), std::string::npos) << why;
    EXPECT_NE(why.find("cannot open data file " + dir + "/gone.raw: does not exist"), std::string::npos) << why;
}

TEST(MetaImageReader, UnreadablePathsAreNamed)
{
    const std::string dir = tempDirectory();
    std::string why = expectReadError(dir + "/nope.mhd");
    EXPECT_NE(why.find(dir + "/nope.mhd: no such file"), std::string::npos) << why;
    std::filesystem::create_directories(dir + "/folder.mha");
    why = expectReadError(dir + "/folder.mha");
    EXPECT_NE(why.find("is a directory"), std::string::npos) << why;
    expectRejected("nodata.mhd", header, "no ElementDataFile entry");
}

TEST(MetaImageReader, NonFiniteOrNonPositiveSpacingIsRejected)
{
    const std::string rest = "ElementType = MET_UCHAR\nElementDataFile = LOCAL\nx";
    expectRejected("nan.mha", "NDims = 3\nDimSize = 1 1 1\nElementSpacing = 1 nan 1\n" + rest, "'nan' is not a positive finite spacing");
    expectRejected("inf.mha", "NDims = 3\nDimSize = 1 1 1\nElementSpacing = inf 1 1\n" + rest, "'inf' is not a positive finite spacing");
    expectRejected("zero.mha", "NDims = 3\nDimSize = 1 1 1\nElementSpacing = 1 1 0\n" + rest, "'0' is not a positive finite spacing");
    expectRejected("neg.mha", "NDims = 3\nDimSize = 1 1 1\nElementSpacing = -1 1 1\n" + rest, "'-1' is not a positive finite spacing");
}

TEST(MetaImageReader, ReportsProgressAndCanBeCancelled)
{
    const std::string dir = tempDirectory();
    writeFile(dir + "/big.mha", "NDims = 3\nDimSize = 128 128 64\nElementType = MET_USHORT\nElementDataFile = LOCAL\n" +
                                    uint16Ramp(128 * 128 * 64, 3));
    std::vector<double> seen;
    const LoadProgress record = [&](double f) {
        seen.push_back(f);
        return true;
    };
    readVolumeFile(dir + "/big.mha", withLoadProgress(nullptr, &record).get());
    ASSERT_GE(seen.size(), 3u);
    EXPECT_EQ(seen.back(), 1.0);
    const LoadProgress cancel = [](double f) { return f < 0.25; };
    try {
        readVolumeFile(dir + "/big.mha", withLoadProgress(nullptr, &cancel).get());
        ADD_FAILURE() << "cancelled load succeeded";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find(dir + "/big.mha: cancelled"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace volren::test
