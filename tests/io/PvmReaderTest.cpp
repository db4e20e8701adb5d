// PVM loader: synthetic uncompressed PVM, PVM2 and PVM3 files (8 and 16 bit) written here read
// back exactly; bad files fail with the file name and the reason.
#include "TestData.h"

#include <volume_model/ReadVolume.h>

#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
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
    check("dds.pvm", "DDS v3d\n\x01\x02\x03", "DDS-compressed PVM");
    check("dds3e.pvm", "DDS v3e\n\x01\x02\x03", "not supported yet");
    const std::string missing = dir + "/nope.pvm";
    EXPECT_NE(expectReadError(missing).find(missing + ": no such file"), std::string::npos);
}

}  // namespace
}  // namespace volren::test
