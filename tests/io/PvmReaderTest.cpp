// PVM loader: synthetic uncompressed PVM, PVM2 and PVM3 files (8 and 16 bit) written here read
// back exactly; bad files fail with the file name and the reason.
#include "TestData.h"

#include <volume_model/ReadVolume.h>

#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <iterator>
#include <string>

namespace volren::test {
namespace {

void writeAll(const std::string& path, const std::string& bytes)
{
    std::ofstream(path, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
}


/// 8-bit voxels i*7+3 (mod 256) of a 5x4x3 grid.
std::string bytes8()
{
    std::string out;
    for (int i = 0; i < 60; ++i) out += char((i * 7 + 3) & 0xff);
    return out;
}

/// 16-bit voxels i*1111 (mod 65536), big-endian, of a 5x4x3 grid.
std::string bytes16()
{
    std::string out;
    for (int i = 0; i < 60; ++i) {
        const std::uint16_t v = std::uint16_t(i * 1111);
        out += char(v >> 8);
        out += char(v & 0xff);
    }
    return out;
}

TEST(PvmReader, Pvm1EightBitReadsBackExactly)
{
    const std::string path = tempDirectory() + "/v1.pvm";
    writeAll(path, "PVM\n# a comment line\n5 4 3\n1\n" + bytes8());
    osg::ref_ptr<Volume> v = readVolumeFile(path);
    EXPECT_EQ(v->dims(), osg::Vec3i(5, 4, 3));
    EXPECT_EQ(v->type(), VoxelType::UInt8);
    EXPECT_EQ(v->spacing(), osg::Vec3d(1, 1, 1));
    EXPECT_EQ(v->sourceFile, path);
    for (int i = 0; i < 60; ++i) ASSERT_EQ(v->value(std::size_t(i)), double((i * 7 + 3) & 0xff)) << i;
}

TEST(PvmReader, Pvm2SixteenBitBigEndianReadsBackExactly)
{
    const std::string path = tempDirectory() + "/v2.pvm";
    writeAll(path, "PVM2\n5 4 3\n0.5 0.25 2\n2\n" + bytes16());
    osg::ref_ptr<Volume> v = readVolumeFile(path);
    EXPECT_EQ(v->dims(), osg::Vec3i(5, 4, 3));
    EXPECT_EQ(v->type(), VoxelType::UInt16);
    EXPECT_EQ(v->spacing(), osg::Vec3d(0.5, 0.25, 2.0));
    for (int i = 0; i < 60; ++i) ASSERT_EQ(v->value(std::size_t(i)), double(std::uint16_t(i * 1111))) << i;
    EXPECT_EQ(v->value(4, 3, 2), double(std::uint16_t(59 * 1111)));
}

TEST(PvmReader, Pvm3WithTrailingDescriptionStrings)
{
    const std::string path = tempDirectory() + "/v3.pvm";
    writeAll(path, "PVM3\n5 4 3\n1 1 3.5\n1\n" + bytes8() + std::string("a test volume\0nobody\0\0\0", 24));
    osg::ref_ptr<Volume> v = readVolumeFile(path);
    EXPECT_EQ(v->dims(), osg::Vec3i(5, 4, 3));
    EXPECT_EQ(v->spacing(), osg::Vec3d(1, 1, 3.5));
    for (int i = 0; i < 60; ++i) ASSERT_EQ(v->value(std::size_t(i)), double((i * 7 + 3) & 0xff)) << i;
}

// --- DDS-compressed files, encoded by the V^3 library's own writer (tests/io/data/pvm-dds) ---

std::string ddsFile(const std::string& name)
{
    return std::string(VOLREN_SOURCE_DIR) + "/tests/io/data/pvm-dds/" + name;
}

TEST(PvmReader, DdsV3dEightBitDecodesToTheEncodedVoxels)
{
    osg::ref_ptr<Volume> v = readVolumeFile(ddsFile("v3d-uint8-37x23x11.pvm"));
    ASSERT_EQ(v->dims(), osg::Vec3i(37, 23, 11));
    EXPECT_EQ(v->type(), VoxelType::UInt8);
    for (int z = 0; z < 11; ++z)
        for (int y = 0; y < 23; ++y)
            for (int x = 0; x < 37; ++x)
                ASSERT_EQ(v->value(x, y, z), double((7 * x + 13 * y + 29 * z + (x * y) % 11) % 256)) << x << "," << y << "," << z;
}

TEST(PvmReader, DdsV3dSixteenBitUndoesTheByteInterleaving)
{
    osg::ref_ptr<Volume> v = readVolumeFile(ddsFile("v3d-uint16-19x17x5.pvm"));
    ASSERT_EQ(v->dims(), osg::Vec3i(19, 17, 5));
    EXPECT_EQ(v->type(), VoxelType::UInt16);
    EXPECT_EQ(v->spacing(), osg::Vec3d(0.5, 0.25, 2.0));
    for (int z = 0; z < 5; ++z)
        for (int y = 0; y < 17; ++y)
            for (int x = 0; x < 19; ++x)
                ASSERT_EQ(v->value(x, y, z), double((1000 * x + 37 * y + 4001 * z + (x * y * z) % 97) % 65536))
                    << x << "," << y << "," << z;
}

TEST(PvmReader, DdsPvm3KeepsItsSpacingAndStrings)
{
    osg::ref_ptr<Volume> v = readVolumeFile(ddsFile("v3d-pvm3-9x8x7.pvm"));
    ASSERT_EQ(v->dims(), osg::Vec3i(9, 8, 7));
    EXPECT_EQ(v->spacing(), osg::Vec3d(1, 1, 3.5));
    for (int z = 0; z < 7; ++z)
        for (int y = 0; y < 8; ++y)
            for (int x = 0; x < 9; ++x) ASSERT_EQ(v->value(x, y, z), double((x * x + 3 * y + 50 * z) % 256));
}

TEST(PvmReader, DdsV3eLargerThanOneInterleaveBlockDecodesExactly)
{
    // 256 x 256 x 129 x 2 bytes = 16.9 MB: more than one 2^24-byte block, so both the full-block
    // and the remainder de-interleaving run.
    osg::ref_ptr<Volume> v = readVolumeFile(ddsFile("v3e-uint16-256x256x129.pvm"));
    ASSERT_EQ(v->dims(), osg::Vec3i(256, 256, 129));
    EXPECT_EQ(v->type(), VoxelType::UInt16);
    EXPECT_EQ(v->spacing(), osg::Vec3d(1, 1, 1.5));
    std::size_t wrong = 0;
    for (int z = 0; z < 129; ++z)
        for (int y = 0; y < 256; ++y)
            for (int x = 0; x < 256; ++x) wrong += v->value(x, y, z) != double((3 * x + 257 * y + 499 * z) % 65536);
    EXPECT_EQ(wrong, 0u);
}

TEST(PvmReader, BadFilesAreRejectedWithFileAndReason)
{
    const std::string dir = tempDirectory();
    auto check = [&](const std::string& name, const std::string& bytes, const std::string& expect) {
        writeAll(dir + "/" + name, bytes);
        const std::string why = expectReadError(dir + "/" + name);
        EXPECT_NE(why.find(dir + "/" + name), std::string::npos) << why;
        EXPECT_NE(why.find(expect), std::string::npos) << name << ": " << why;
    };
    check("truncated.pvm", "PVM2\n5 4 3\n1 1 1\n2\n" + bytes16().substr(0, 99), "truncated: voxel data needs 120 bytes");
    check("header.pvm", "PVM2\n5 4 3\n", "truncated: PVM header");
    check("empty.pvm", "", "truncated");
    check("magic.pvm", "PVM9\n5 4 3\n1\n" + bytes8(), "not a PVM file");
    check("zero.pvm", "PVM\n5 0 3\n1\n", "must be positive");
    check("negative.pvm", "PVM\n5 -4 3\n1\n", "must be positive");
    check("fraction.pvm", "PVM\n5 4.5 3\n1\n", "not an integer");
    check("overflow.pvm", "PVM\n5 99999999999 3\n1\n", "not an integer in range");
    check("huge.pvm", "PVM\n100000 100000 100000\n1\n", "exceeds the limit");
    check("words.pvm", "PVM\nfive 4 3\n1\n", "not a number");
    check("count.pvm", "PVM\n5 4\n1\n", "expected 3 numbers");
    check("spacing.pvm", "PVM2\n5 4 3\n1 0 1\n1\n" + bytes8(), "spacing 0");
    check("rgb.pvm", "PVM\n5 4 3\n3\n" + bytes8() + bytes8() + bytes8(), "unsupported PVM voxel size 3");
    check("dds.pvm", std::string("DDS v3d\n\xff\xff\xff", 11), "truncated DDS stream");
    check("dds-empty.pvm", std::string("DDS v3e\n\x00\x00\x00\x00", 12), "empty DDS stream");
    // A valid stream cut short: the decoder notices reading past the end.
    std::ifstream whole(ddsFile("v3d-uint8-37x23x11.pvm"), std::ios::binary);
    const std::string dds((std::istreambuf_iterator<char>(whole)), std::istreambuf_iterator<char>());
    check("dds-cut.pvm", dds.substr(0, dds.size() / 2), "truncated DDS stream");
    const std::string missing = dir + "/nope.pvm";
    EXPECT_NE(expectReadError(missing).find(missing + ": no such file"), std::string::npos);
}

}  // namespace
}  // namespace volren::test
