// Headerless .raw volumes (layout from reader options or FILE.raw.txt) and QVis .dat headers:
// layouts, byte order, gzip, and bad files that must fail with the file name and the reason.
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

std::string floatRamp(int n)
{
    std::string bytes;
    for (int i = 0; i < n; ++i) {
        const float v = 0.5f * float(i) - 3.0f;
        bytes.append(reinterpret_cast<const char*>(&v), 4);
    }
    return bytes;
}


osg::ref_ptr<osgDB::Options> opts(const std::string& text) { return new osgDB::Options(text); }

void expectRejected(const std::string& path, const osgDB::Options* options, const std::string& reason)
{
    const std::string why = expectReadError(path, options);
    EXPECT_NE(why.find(path), std::string::npos) << why;
    EXPECT_NE(why.find(reason), std::string::npos) << path << ": " << why;
}

void expectRamp(const Volume& v, const std::string& what)
{
    ASSERT_EQ(v.dims(), osg::Vec3i(2, 3, 4)) << what;
    EXPECT_EQ(v.type(), VoxelType::Float32) << what;
    for (int i = 0; i < 24; ++i) ASSERT_EQ(v.value(std::size_t(i)), 0.5 * i - 3.0) << what << " " << i;
}

TEST(RawReader, LayoutFromOptionsSidecarOrBoth)
{
    const std::string dir = tempDirectory();
    writeFile(dir + "/a.raw", std::string(16, 'H') + floatRamp(24));
    osg::ref_ptr<Volume> v = readVolumeFile(dir + "/a.raw", opts("dims=2,3,4 type=float32 skip=16 spacing=1,1,2").get());
    expectRamp(*v, "options");
    EXPECT_EQ(v->spacing(), osg::Vec3d(1, 1, 2));

    writeFile(dir + "/b.raw", floatRamp(24));
    writeFile(dir + "/b.raw.txt", "# sidecar\ndims=2,3,4\ntype=float\nendian=little spacing=0.5,0.5,1\n");
    v = readVolumeFile(dir + "/b.raw");
    expectRamp(*v, "sidecar");
    EXPECT_EQ(v->spacing(), osg::Vec3d(0.5, 0.5, 1));
    v = readVolumeFile(dir + "/b.raw", opts("spacing=3,3,3").get());  // options override the sidecar
    EXPECT_EQ(v->spacing(), osg::Vec3d(3, 3, 3));

    registerPluginPath();
    osg::ref_ptr<osg::Object> object = osgDB::readRefObjectFile(dir + "/b.raw");
    ASSERT_NE(dynamic_cast<Volume*>(object.get()), nullptr) << "osgDB::readRefObjectFile did not give a volren::Volume";
    object = osgDB::readRefObjectFile(dir + "/a.raw", opts("dims=2,3,4 type=float32 skip=16").get());
    ASSERT_NE(dynamic_cast<Volume*>(object.get()), nullptr);
    EXPECT_TRUE(osgDB::readRefNodeFile(dir + "/b.raw").valid());
}

TEST(RawReader, BigEndianGzipAndTrailingData)
{
    const std::string dir = tempDirectory();
    std::string big = floatRamp(24);
    for (std::size_t i = 0; i < big.size(); i += 4) std::reverse(big.begin() + long(i), big.begin() + long(i + 4));
    writeFile(dir + "/big.raw", big);
    expectRamp(*readVolumeFile(dir + "/big.raw", opts("dims=2,3,4 type=float32 endian=big").get()), "big");
    const std::string plain = floatRamp(24);
    uLongf size = compressBound(uLong(plain.size()));
    std::string packed(size, '\0');
    compress2(reinterpret_cast<Bytef*>(&packed[0]), &size, reinterpret_cast<const Bytef*>(plain.data()), uLong(plain.size()), 9);
    packed.resize(size);
    writeFile(dir + "/z.raw", packed);
    expectRamp(*readVolumeFile(dir + "/z.raw", opts("dims=2,3,4 type=float32 encoding=gzip").get()), "zlib");
    writeFile(dir + "/tail.raw", std::string(7, 'h') + plain);
    expectRamp(*readVolumeFile(dir + "/tail.raw", opts("dims=2,3,4 type=float32 skip=-1").get()), "skip=-1");
}

TEST(RawReader, ReadsQvisDatHeaders)
{
    const std::string dir = tempDirectory();
    std::string bytes;
    for (int i = 0; i < 24; ++i) {
        const std::uint16_t v = std::uint16_t(i * 2000);
        bytes.append(reinterpret_cast<const char*>(&v), 2);
    }
    writeFile(dir + "/vol.raw", bytes);
    writeFile(dir + "/vol.dat", "ObjectFileName: vol.raw\nTaggedFileName: ---\nResolution:     2 3 4\nSliceThickness: 1 1 1.5\n"
                                "Format:         USHORT\nNbrTags:        0\nObjectType:     TEXTURE_VOLUME_OBJECT\n"
                                "ObjectModel:    I\nGridType:       EQUIDISTANT\n");
    osg::ref_ptr<Volume> v = readVolumeFile(dir + "/vol.dat");
    EXPECT_EQ(v->dims(), osg::Vec3i(2, 3, 4));
    EXPECT_EQ(v->type(), VoxelType::UInt16);
    EXPECT_EQ(v->spacing(), osg::Vec3d(1, 1, 1.5));
    for (int i = 0; i < 24; ++i) ASSERT_EQ(v->value(std::size_t(i)), 2000.0 * i);
    registerPluginPath();
    EXPECT_NE(dynamic_cast<Volume*>(osgDB::readRefObjectFile(dir + "/vol.dat").get()), nullptr);

    writeFile(dir + "/bad.dat", "ObjectFileName: vol.raw\nResolution: 2 3 4\nFormat: DOUBLE\n");
    expectRejected(dir + "/bad.dat", nullptr, "unsupported Format 'DOUBLE'");
    writeFile(dir + "/lost.dat", "ObjectFileName: missing.raw\nResolution: 2 3 4\nFormat: UCHAR\n");
    expectRejected(dir + "/lost.dat", nullptr, "cannot open data file " + dir + "/missing.raw: does not exist");
    writeFile(dir + "/other.dat", "just some numbers 1 2 3\n");
    expectRejected(dir + "/other.dat", nullptr, "not a QVis .dat header");
}

TEST(RawReader, MissingLayoutIsRejected)
{
    const std::string dir = tempDirectory();
    writeFile(dir + "/x.raw", floatRamp(24));
    expectRejected(dir + "/x.raw", nullptr, "needs dims=X,Y,Z and type=");
    writeFile(dir + "/y.raw", floatRamp(24));
    writeFile(dir + "/y.raw.txt", "dims=2,3,4 type=float32 colour=red\n");
    const std::string why = expectReadError(dir + "/y.raw");
    EXPECT_NE(why.find(dir + "/y.raw.txt: unknown entry 'colour=red'"), std::string::npos) << why;
}

TEST(RawReader, TruncatedPayloadIsRejected)
{
    const std::string dir = tempDirectory();
    writeFile(dir + "/short.raw", floatRamp(23));
    expectRejected(dir + "/short.raw", opts("dims=2,3,4 type=float32").get(), "truncated");
}

TEST(RawReader, HeaderClaimingMoreThanTheDataFileHoldsIsRefusedBeforeAllocating)
{
    // Found by fuzz_raw: a sidecar asking for 2048 x 2048 x 1024 voxels of a 10-byte file made
    // the payload reader allocate 4 GiB first; now the data file size is checked before that
    // (for gzip: the most deflate can expand it to).
    const std::string dir = tempDirectory();
    writeFile(dir + "/liar.raw", std::string(10, '\1'));
    writeFile(dir + "/liar.raw.txt", "dims=2048,2048,1024 type=uint8\n");
    expectRejected(dir + "/liar.raw", nullptr,
                   "truncated: data file " + dir + "/liar.raw holds 10 bytes of voxel data, the header needs 4294967296");
    writeFile(dir + "/liar.raw.txt", "dims=2048,2048,1024 type=uint8 encoding=gzip\n");
    expectRejected(dir + "/liar.raw", nullptr, "truncated: 10 bytes of compressed data in " + dir +
                                                   "/liar.raw cannot decode to the 4294967296 bytes the header needs");
}

TEST(RawReader, HeaderSizeMismatchIsRejected)
{
    const std::string dir = tempDirectory();
    writeFile(dir + "/long.raw", floatRamp(25));
    expectRejected(dir + "/long.raw", opts("dims=2,3,4 type=float32").get(), "size mismatch");
}

TEST(RawReader, ZeroNegativeAndOverflowingSizesAreRejected)
{
    const std::string dir = tempDirectory();
    writeFile(dir + "/v.raw", floatRamp(24));
    expectRejected(dir + "/v.raw", opts("dims=0,3,4 type=float32").get(), "dimensions must be positive");
    expectRejected(dir + "/v.raw", opts("dims=2,-3,4 type=float32").get(), "dimensions must be positive");
    expectRejected(dir + "/v.raw", opts("dims=65536,65536,65536 type=float32").get(), "exceeds the limit");
    expectRejected(dir + "/v.raw", opts("dims=2,3,99999999999 type=float32").get(), "too large");
}

TEST(RawReader, UnknownTypeOrEncodingIsRejected)
{
    const std::string dir = tempDirectory();
    writeFile(dir + "/v.raw", floatRamp(24));
    expectRejected(dir + "/v.raw", opts("dims=2,3,4 type=complex64").get(), "unknown voxel type 'complex64'");
    expectRejected(dir + "/v.raw", opts("dims=2,3,4 type=float32 encoding=lzma").get(), "unknown encoding 'lzma'");
}

TEST(RawReader, CorruptGzipStreamIsRejected)
{
    const std::string dir = tempDirectory();
    writeFile(dir + "/bad.raw", std::string("\x1f\x8b\x08\x00\x00\x00\x00\x00\x00\x03garbage-garbage", 25));
    expectRejected(dir + "/bad.raw", opts("dims=2,3,4 type=float32 encoding=gzip").get(), "corrupt compressed data");
}

TEST(RawReader, UnreadablePathsAreNamed)
{
    const std::string dir = tempDirectory();
    std::string why = expectReadError(dir + "/nope.raw");
    EXPECT_NE(why.find(dir + "/nope.raw: no such file"), std::string::npos) << why;
    std::filesystem::create_directories(dir + "/folder.dat");
    why = expectReadError(dir + "/folder.dat");
    EXPECT_NE(why.find("is a directory"), std::string::npos) << why;
}

TEST(RawReader, NonFiniteOrNonPositiveSpacingIsRejected)
{
    const std::string dir = tempDirectory();
    writeFile(dir + "/v.raw", floatRamp(24));
    expectRejected(dir + "/v.raw", opts("dims=2,3,4 type=float32 spacing=1,nan,1").get(), "must be three finite numbers");
    expectRejected(dir + "/v.raw", opts("dims=2,3,4 type=float32 spacing=1,1,0").get(), "spacing 0.000000 along axis 2 is not positive");
    expectRejected(dir + "/v.raw", opts("dims=2,3,4 type=float32 spacing=-1,1,1").get(), "along axis 0 is not positive");
    writeFile(dir + "/v.raw", floatRamp(24));
    writeFile(dir + "/v.dat", "ObjectFileName: v.raw\nResolution: 2 3 4\nSliceThickness: 1 inf 1\nFormat: FLOAT\n");
    expectRejected(dir + "/v.dat", nullptr, "SliceThickness '1 inf 1' must be three finite numbers");
}

TEST(RawReader, ReportsProgressAndCanBeCancelled)
{
    const std::string dir = tempDirectory();
    writeFile(dir + "/big.raw", std::string(std::size_t(4) << 20, '\x7'));
    const auto layout = opts("dims=256,256,64 type=uint8");
    std::vector<double> seen;
    const LoadProgress record = [&](double f) {
        seen.push_back(f);
        return true;
    };
    readVolumeFile(dir + "/big.raw", withLoadProgress(layout.get(), &record).get());
    ASSERT_GE(seen.size(), 4u);
    EXPECT_EQ(seen.front(), 0.0);
    EXPECT_EQ(seen.back(), 1.0);
    int calls = 0;
    const LoadProgress cancel = [&](double) { return ++calls < 3; };
    const std::string why = expectReadError(dir + "/big.raw", withLoadProgress(layout.get(), &cancel).get());
    EXPECT_NE(why.find(dir + "/big.raw: cancelled"), std::string::npos) << why;
    EXPECT_EQ(calls, 3);
}

}  // namespace
}  // namespace volren::test
