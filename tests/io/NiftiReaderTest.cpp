// NIfTI-1 loader: real files from ../shared/data (expected values from its MANIFEST), byte
// order, value scaling, and bad files that must fail with the file name and the reason.
#include "TestData.h"

#include <volume_model/LengthUnit.h>
#include <volume_model/ReadVolume.h>

#include <osgDB/ReadFile>
#include <gtest/gtest.h>
#include <zlib.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace volren::test {
namespace {

/// Reads a whole (possibly gzip-compressed) file.
std::vector<char> readAll(const std::string& path, bool gunzip)
{
    std::vector<char> bytes;
    if (gunzip) {
        gzFile gz = gzopen(path.c_str(), "rb");
        char buf[1 << 16];
        int n;
        while ((n = gzread(gz, buf, sizeof(buf))) > 0) bytes.insert(bytes.end(), buf, buf + n);
        gzclose(gz);
    } else {
        std::ifstream in(path, std::ios::binary);
        bytes.assign(std::istreambuf_iterator<char>(in), {});
    }
    return bytes;
}

void writeAll(const std::string& path, const std::vector<char>& bytes)
{
    std::ofstream(path, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
}

/// A minimal single-file NIfTI-1 image in little- or big-endian byte order.
struct NiftiBuilder
{
    short dim[8] = {3, 2, 3, 4, 1, 1, 1, 1};
    short datatype = 4, bitpix = 16;  // int16
    float pixdim[8] = {1, 0.5f, 0.75f, 2.0f, 1, 1, 1, 1};
    float slope = 0, inter = 0;
    bool bigEndian = false;
    std::vector<char> voxels;  // native order; swapped on write for big-endian

    template <typename T>
    void put(std::vector<char>& h, std::size_t off, T v) const
    {
        std::memcpy(h.data() + off, &v, sizeof(T));
        if (bigEndian) std::reverse(h.begin() + long(off), h.begin() + long(off + sizeof(T)));
    }

    std::vector<char> build() const
    {
        std::vector<char> h(352, 0);
        put<int>(h, 0, 348);
        for (int i = 0; i < 8; ++i) put<short>(h, 40 + 2 * i, dim[i]);
        put<short>(h, 70, datatype);
        put<short>(h, 72, bitpix);
        for (int i = 0; i < 8; ++i) put<float>(h, 76 + 4 * i, pixdim[i]);
        put<float>(h, 108, 352.0f);
        put<float>(h, 112, slope);
        put<float>(h, 116, inter);
        std::memcpy(h.data() + 344, "n+1\0", 4);
        std::vector<char> body = voxels;
        const std::size_t width = std::size_t(bitpix / 8);
        if (bigEndian && width > 1)
            for (std::size_t i = 0; i + width <= body.size(); i += width)
                std::reverse(body.begin() + long(i), body.begin() + long(i + width));
        h.insert(h.end(), body.begin(), body.end());
        return h;
    }
};


TEST(NiftiReader, ReadsColin27HeadAsInTheManifest)
{
    VOLREN_REQUIRE_SHARED_DATA();
    const std::string path = sharedData("mri/ch2.nii.gz");
    osg::ref_ptr<Volume> v = readVolumeFile(path);
    EXPECT_EQ(v->dims(), osg::Vec3i(181, 217, 181));
    EXPECT_EQ(v->type(), VoxelType::UInt8);
    EXPECT_EQ(v->spacing(), osg::Vec3d(1, 1, 1));
    EXPECT_EQ(v->sourceFile, path);
    // Independent check of voxel order: voxel (i,j,k) is byte vox_offset + i + 181*(j + 217*k).
    const std::vector<char> raw = readAll(path, true);
    for (auto [i, j, k] : {std::tuple{90, 108, 90}, {10, 200, 5}, {180, 0, 180}, {33, 150, 120}})
        EXPECT_EQ(v->value(i, j, k), double(std::uint8_t(raw[352 + i + 181 * (j + 217 * k)]))) << i << "," << j << "," << k;
}

TEST(NiftiReader, ReadsCtAngiographyWithScaleSlope)
{
    VOLREN_REQUIRE_SHARED_DATA();
    osg::ref_ptr<Volume> v = readVolumeFile(sharedData("ct/CT_AVM.nii.gz"));
    EXPECT_EQ(v->dims(), osg::Vec3i(256, 242, 154));
    EXPECT_EQ(lengthUnitOf(*v), "mm") << "xyzt_units 10: mm and seconds";
    EXPECT_EQ(v->type(), VoxelType::UInt8);
    EXPECT_NEAR(v->spacing().x(), 0.7199, 1e-4);
    EXPECT_NEAR(v->spacing().y(), 0.7209, 1e-4);
    EXPECT_NEAR(v->spacing().z(), 1.0, 1e-6);
    EXPECT_NEAR(v->rescaleSlope(), 2.2086, 1e-4);
    EXPECT_NEAR(v->valueRange().second, 563.2, 0.1);  // the MANIFEST's scaled maximum
}

TEST(NiftiReader, ReadsBonsaiBenchmarkVolume)
{
    VOLREN_REQUIRE_SHARED_DATA();
    osg::ref_ptr<Volume> v = readVolumeFile(sharedData("ct/bonsai.nii.gz"));
    EXPECT_EQ(v->dims(), osg::Vec3i(256, 256, 256));
    EXPECT_EQ(v->type(), VoxelType::UInt8);
    EXPECT_EQ(v->spacing(), osg::Vec3d(1, 1, 1));
}

TEST(NiftiReader, StockOsgToolsPathThroughTheGzPluginGivesTheSameVolume)
{
    VOLREN_REQUIRE_SHARED_DATA();
    const std::string path = sharedData("mri/ch2.nii.gz");
    registerPluginPath();
    osg::ref_ptr<osg::Object> object = osgDB::readRefObjectFile(path);
    auto* v = dynamic_cast<Volume*>(object.get());
    ASSERT_NE(v, nullptr) << "osgDB::readRefObjectFile did not give a volren::Volume";
    EXPECT_EQ(v->dims(), osg::Vec3i(181, 217, 181));
    osg::ref_ptr<osg::Node> scene = osgDB::readRefNodeFile(path);
    ASSERT_TRUE(scene.valid()) << "a bare volume read as a node gets the default scene";
}

TEST(NiftiReader, BigAndLittleEndianFilesGiveTheSameValues)
{
    const std::string dir = tempDirectory();
    NiftiBuilder b;
    std::vector<std::int16_t> values(24);
    for (int i = 0; i < 24; ++i) values[i] = std::int16_t(i * 1000 - 12000);
    b.voxels.assign(reinterpret_cast<char*>(values.data()), reinterpret_cast<char*>(values.data()) + 48);
    b.slope = 0.5f;
    b.inter = 10.0f;
    writeAll(dir + "/le.nii", b.build());
    b.bigEndian = true;
    writeAll(dir + "/be.nii", b.build());
    for (const char* name : {"/le.nii", "/be.nii"}) {
        osg::ref_ptr<Volume> v = readVolumeFile(dir + name);
        EXPECT_EQ(v->dims(), osg::Vec3i(2, 3, 4)) << name;
        EXPECT_EQ(v->type(), VoxelType::Int16);
        EXPECT_EQ(v->spacing(), osg::Vec3d(0.5, 0.75, 2.0));
        for (int i = 0; i < 24; ++i) ASSERT_DOUBLE_EQ(v->value(std::size_t(i)), values[i] * 0.5 + 10.0) << name << " " << i;
    }
}

TEST(NiftiReader, WideIntegerAndDoubleVoxelsBecomeFloat)
{
    const std::string dir = tempDirectory();
    NiftiBuilder b;
    b.datatype = 64;  // float64
    b.bitpix = 64;
    std::vector<double> values(24);
    for (int i = 0; i < 24; ++i) values[i] = 0.125 * i - 1.0;
    b.voxels.assign(reinterpret_cast<char*>(values.data()), reinterpret_cast<char*>(values.data()) + 24 * 8);
    writeAll(dir + "/d.nii", b.build());
    osg::ref_ptr<Volume> v = readVolumeFile(dir + "/d.nii");
    EXPECT_EQ(v->type(), VoxelType::Float32);
    for (int i = 0; i < 24; ++i) EXPECT_DOUBLE_EQ(v->value(std::size_t(i)), values[i]);
}

TEST(NiftiReader, TruncatedCopiesOfARealFileAreRejectedWithFileAndReason)
{
    VOLREN_REQUIRE_SHARED_DATA();
    const std::string source = sharedData("mri/ch2.nii.gz");
    const std::string dir = tempDirectory();
    std::vector<char> plain = readAll(source, true);
    plain.resize(plain.size() / 2);
    writeAll(dir + "/half.nii", plain);
    std::string why = expectReadError(dir + "/half.nii");
    EXPECT_NE(why.find(dir + "/half.nii"), std::string::npos) << why;
    EXPECT_NE(why.find("truncated"), std::string::npos) << why;

    std::vector<char> packed = readAll(source, false);
    packed.resize(packed.size() * 6 / 10);
    writeAll(dir + "/cut.nii.gz", packed);
    why = expectReadError(dir + "/cut.nii.gz");
    EXPECT_NE(why.find(dir + "/cut.nii.gz"), std::string::npos) << why;
    EXPECT_TRUE(why.find("truncated") != std::string::npos || why.find("unexpected end") != std::string::npos) << why;

    writeAll(dir + "/tiny.nii", std::vector<char>(100, 0));
    why = expectReadError(dir + "/tiny.nii");
    EXPECT_NE(why.find("truncated: NIfTI header"), std::string::npos) << why;
}

TEST(NiftiReader, HeaderClaimingMoreVoxelsThanTheFileHoldsIsRefusedBeforeAllocating)
{
    // Found by fuzz_nii: 362 bytes whose header asks for 2048 x 2048 x 1024 uint8 voxels made the
    // reader allocate 4 GiB before reading; now the file size (or, gzip-compressed, the most it
    // can expand to) is checked first.
    const std::string dir = tempDirectory();
    NiftiBuilder liar;
    liar.dim[1] = 2048, liar.dim[2] = 2048, liar.dim[3] = 1024;
    liar.datatype = 2, liar.bitpix = 8;
    liar.voxels.assign(10, 1);
    const std::vector<char> bytes = liar.build();
    writeAll(dir + "/liar.nii", bytes);
    std::string why = expectReadError(dir + "/liar.nii");
    EXPECT_NE(why.find(dir + "/liar.nii: truncated: voxel data needs 4294967296 bytes"), std::string::npos) << why;

    gzFile gz = gzopen((dir + "/liar.nii.gz").c_str(), "wb");
    ASSERT_TRUE(gz);
    gzwrite(gz, bytes.data(), unsigned(bytes.size()));
    gzclose(gz);
    why = expectReadError(dir + "/liar.nii.gz");
    EXPECT_NE(why.find(dir + "/liar.nii.gz: truncated: voxel data needs 4294967296 bytes"), std::string::npos) << why;
}

TEST(NiftiReader, CorruptHeadersAreRejectedWithTheReason)
{
    const std::string dir = tempDirectory();
    auto check = [&](const std::string& name, const std::vector<char>& bytes, const std::string& expect) {
        writeAll(dir + "/" + name, bytes);
        const std::string why = expectReadError(dir + "/" + name);
        EXPECT_NE(why.find(dir + "/" + name), std::string::npos) << why;
        EXPECT_NE(why.find(expect), std::string::npos) << name << ": " << why;
    };
    NiftiBuilder good;
    good.voxels.assign(48, 0);

    std::vector<char> notNifti = good.build();
    notNifti[0] = 7;
    check("magic.nii", notNifti, "not a NIfTI-1 file");

    NiftiBuilder negative = good;
    negative.dim[2] = -3;
    check("negative.nii", negative.build(), "dim[2] = -3 is not positive");

    NiftiBuilder huge = good;
    huge.dim[1] = huge.dim[2] = huge.dim[3] = 32767;
    check("huge.nii", huge.build(), "exceeds the limit");

    NiftiBuilder rgb = good;
    rgb.datatype = 128;
    rgb.bitpix = 24;
    check("rgb.nii", rgb.build(), "unsupported NIfTI datatype RGB24");

    std::vector<char> pair = good.build();
    std::memcpy(pair.data() + 344, "ni1\0", 4);
    check("pair.nii", pair, ".hdr/.img pair");

    std::vector<char> badGzip = {0x1f, char(0x8b), 8, 0, 0, 0, 0, 0, 0, 3, 'g', 'a', 'r', 'b', 'a', 'g', 'e'};
    check("garbage.nii.gz", badGzip, "");
}

TEST(NiftiReader, MissingFilesAndDirectoriesAreNamed)
{
    const std::string dir = tempDirectory();
    std::string why = expectReadError(dir + "/nope.nii");
    EXPECT_NE(why.find(dir + "/nope.nii: no such file"), std::string::npos) << why;
    std::filesystem::create_directories(dir + "/folder.nii");
    why = expectReadError(dir + "/folder.nii");
    EXPECT_NE(why.find("is a directory"), std::string::npos) << why;
}

}  // namespace
}  // namespace volren::test
