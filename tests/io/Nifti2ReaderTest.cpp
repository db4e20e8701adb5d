// NIfTI-2 in the NIfTI loader (540-byte header, 64-bit dims, double pixdim and scaling) and the
// voxel-to-world matrix from sform / qform / pixdim of both versions; synthetic files written
// here read back exactly, bad ones fail with the file name and the reason.
#include "TestData.h"

#include <volume_model/LengthUnit.h>
#include <volume_model/ReadVolume.h>

#include <osg/Matrixd>
#include <osg/ValueObject>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>

namespace volren::test {
namespace {

void writeAll(const std::string& path, const std::vector<char>& bytes)
{
    std::ofstream(path, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
}


/// A minimal single-file NIfTI-2 image (header, 4 extension bytes, voxels) in either byte order.
struct Nifti2Builder
{
    std::int64_t dim[8] = {3, 40000, 1, 2, 1, 1, 1, 1};  // x beyond NIfTI-1's int16 range
    short datatype = 4, bitpix = 16;                      // int16
    double pixdim[8] = {1, 0.3, 0.7, 1.1, 1, 1, 1, 1};    // not representable as float
    double slope = 0.25, inter = -7.5;
    std::int64_t voxOffset = 544;
    int qformCode = 0, sformCode = 0;
    int xyztUnits = 0;
    double quatern[3] = {0, 0, 0}, qoffset[3] = {0, 0, 0};
    double srow[3][4] = {};
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
        std::vector<char> h(544, 0);
        put<int>(h, 0, 540);
        std::memcpy(h.data() + 4, "n+2\0\r\n\032\n", 8);
        put<short>(h, 12, datatype);
        put<short>(h, 14, bitpix);
        for (int i = 0; i < 8; ++i) put<std::int64_t>(h, 16 + 8 * i, dim[i]);
        for (int i = 0; i < 8; ++i) put<double>(h, 104 + 8 * i, pixdim[i]);
        put<std::int64_t>(h, 168, voxOffset);
        put<double>(h, 176, slope);
        put<double>(h, 184, inter);
        put<int>(h, 344, qformCode);
        put<int>(h, 348, sformCode);
        for (int i = 0; i < 3; ++i) put<double>(h, 352 + 8 * i, quatern[i]);
        for (int i = 0; i < 3; ++i) put<double>(h, 376 + 8 * i, qoffset[i]);
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 4; ++c) put<double>(h, 400 + 32 * r + 8 * c, srow[r][c]);
        put<int>(h, 500, xyztUnits);
        std::vector<char> body = voxels;
        const std::size_t width = std::size_t(bitpix / 8);
        if (bigEndian && width > 1)
            for (std::size_t i = 0; i + width <= body.size(); i += width)
                std::reverse(body.begin() + long(i), body.begin() + long(i + width));
        h.insert(h.end(), body.begin(), body.end());
        return h;
    }
};

std::vector<std::int16_t> rampValues(std::size_t count)
{
    std::vector<std::int16_t> values(count);
    for (std::size_t i = 0; i < count; ++i) values[i] = std::int16_t(int(i % 60001) - 30000);
    return values;
}

Nifti2Builder rampImage()
{
    Nifti2Builder b;
    const std::vector<std::int16_t> values = rampValues(80000);
    b.voxels.assign(reinterpret_cast<const char*>(values.data()),
                    reinterpret_cast<const char*>(values.data()) + values.size() * 2);
    return b;
}

osg::Matrixd toWorldOf(const Volume& v, std::string* source = nullptr)
{
    osg::Matrixd m;
    EXPECT_TRUE(v.getUserValue("voxelToWorld", m));
    if (source) {
        EXPECT_TRUE(v.getUserValue("voxelToWorldSource", *source));
    }
    return m;
}

TEST(Nifti2Reader, LittleAndBigEndianFilesReadBackExactly)
{
    const std::string dir = tempDirectory();
    Nifti2Builder b = rampImage();
    writeAll(dir + "/le.nii", b.build());
    b.bigEndian = true;
    writeAll(dir + "/be.nii", b.build());
    const std::vector<std::int16_t> values = rampValues(80000);
    for (const char* name : {"/le.nii", "/be.nii"}) {
        osg::ref_ptr<Volume> v = readVolumeFile(dir + name);
        EXPECT_EQ(v->dims(), osg::Vec3i(40000, 1, 2)) << name;
        EXPECT_EQ(v->type(), VoxelType::Int16);
        EXPECT_EQ(v->spacing(), osg::Vec3d(0.3, 0.7, 1.1));  // doubles kept exactly
        EXPECT_EQ(v->rescaleSlope(), 0.25);
        EXPECT_EQ(v->rescaleIntercept(), -7.5);
        for (std::size_t i = 0; i < values.size(); ++i)
            ASSERT_EQ(v->value(i), values[i] * 0.25 - 7.5) << name << " " << i;
        std::string source;
        const osg::Matrixd m = toWorldOf(*v, &source);
        EXPECT_EQ(source, "pixdim");
        EXPECT_NEAR((osg::Vec3d(2, 0, 1) * m - osg::Vec3d(0.6, 0, 1.1)).length(), 0.0, 1e-12);
    }
}

TEST(Nifti2Reader, XyztUnitsGiveTheSpacingsUnit)
{
    // xyzt_units: bits 0-2 the spatial unit (1 m, 2 mm, 3 µm), bits 3-5 time (8 s, ignored).
    const std::string dir = tempDirectory();
    for (const auto& [code, unit] : std::vector<std::pair<int, std::string>>{
             {0, ""}, {1, "m"}, {2 + 8, "mm"}, {3 + 16, "\xC2\xB5m"}, {4, ""}}) {
        Nifti2Builder b = rampImage();
        b.xyztUnits = code;
        writeAll(dir + "/units.nii", b.build());
        EXPECT_EQ(lengthUnitOf(*readVolumeFile(dir + "/units.nii")), unit) << "xyzt_units " << code;
    }
}

TEST(Nifti2Reader, FloatVoxelsAndZeroSlopeMeanUnscaled)
{
    const std::string path = tempDirectory() + "/f.nii";
    Nifti2Builder b;
    b.dim[1] = 2, b.dim[2] = 3, b.dim[3] = 4;
    b.datatype = 16, b.bitpix = 32;
    b.slope = 0.0;
    std::vector<float> values(24);
    for (int i = 0; i < 24; ++i) values[i] = 0.5f * float(i) - 3.0f;
    b.voxels.assign(reinterpret_cast<char*>(values.data()), reinterpret_cast<char*>(values.data()) + 96);
    writeAll(path, b.build());
    osg::ref_ptr<Volume> v = readVolumeFile(path);
    EXPECT_EQ(v->type(), VoxelType::Float32);
    EXPECT_EQ(v->rescaleSlope(), 1.0);
    EXPECT_EQ(v->rescaleIntercept(), 0.0);
    for (int i = 0; i < 24; ++i) EXPECT_EQ(v->value(std::size_t(i)), double(values[i]));
}

TEST(Nifti2Reader, SformWinsOverQform)
{
    const std::string path = tempDirectory() + "/s.nii";
    Nifti2Builder b = rampImage();
    b.qformCode = 1;
    b.quatern[2] = 1.0;  // 180 degrees about z; must be ignored when sform_code > 0
    b.sformCode = 2;
    const double srow[3][4] = {{0, -0.7, 0, 10}, {0.3, 0, 0, -20}, {0, 0, 1.1, 30}};
    std::memcpy(b.srow, srow, sizeof(srow));
    writeAll(path, b.build());
    std::string source;
    const osg::Matrixd m = toWorldOf(*readVolumeFile(path), &source);
    EXPECT_EQ(source, "sform");
    // world = srow * (i, j, k, 1)
    EXPECT_NEAR((osg::Vec3d(5, 1, 1) * m - osg::Vec3d(-0.7 + 10, 1.5 - 20, 1.1 + 30)).length(), 0.0, 1e-12);
}

TEST(Nifti2Reader, QformQuaternionAndQfacGiveTheStandardMatrix)
{
    const std::string path = tempDirectory() + "/q.nii";
    Nifti2Builder b = rampImage();
    b.qformCode = 1;
    b.quatern[2] = std::sqrt(0.5);  // 90 degrees about z: i -> +y, j -> -x
    b.qoffset[0] = 1, b.qoffset[1] = 2, b.qoffset[2] = 3;
    b.pixdim[0] = -1;  // qfac: k -> -z
    writeAll(path, b.build());
    std::string source;
    const osg::Matrixd m = toWorldOf(*readVolumeFile(path), &source);
    EXPECT_EQ(source, "qform");
    EXPECT_NEAR((osg::Vec3d(1, 0, 0) * m - osg::Vec3d(1, 2 + 0.3, 3)).length(), 0.0, 1e-12);
    EXPECT_NEAR((osg::Vec3d(0, 1, 0) * m - osg::Vec3d(1 - 0.7, 2, 3)).length(), 0.0, 1e-12);
    EXPECT_NEAR((osg::Vec3d(0, 0, 1) * m - osg::Vec3d(1, 2, 3 - 1.1)).length(), 0.0, 1e-12);
}

TEST(Nifti2Reader, Nifti1QformIsExposedToo)
{
    // NIfTI-1 header with qform_code 1, identity rotation, offsets (-90, -126, -72).
    std::vector<char> h(352, 0);
    auto put = [&h](std::size_t off, auto v) { std::memcpy(h.data() + off, &v, sizeof(v)); };
    put(0, 348);
    const short dim[8] = {3, 2, 2, 2, 1, 1, 1, 1};
    for (int i = 0; i < 8; ++i) put(40 + 2 * i, dim[i]);
    put(70, short(2));
    put(72, short(8));
    const float pixdim[8] = {1, 2, 3, 4, 1, 1, 1, 1};
    for (int i = 0; i < 8; ++i) put(76 + 4 * i, pixdim[i]);
    put(108, 352.0f);
    put(252, short(1));
    put(268, -90.0f), put(272, -126.0f), put(276, -72.0f);
    std::memcpy(h.data() + 344, "n+1\0", 4);
    h.resize(360, 1);
    const std::string path = tempDirectory() + "/q1.nii";
    writeAll(path, h);
    std::string source;
    const osg::Matrixd m = toWorldOf(*readVolumeFile(path), &source);
    EXPECT_EQ(source, "qform");
    EXPECT_NEAR((osg::Vec3d(1, 1, 1) * m - osg::Vec3d(-88, -123, -68)).length(), 0.0, 1e-9);
}

TEST(Nifti2Reader, BadFilesAreRejectedWithFileAndReason)
{
    const std::string dir = tempDirectory();
    auto check = [&](const std::string& name, const std::vector<char>& bytes, const std::string& expect) {
        writeAll(dir + "/" + name, bytes);
        const std::string why = expectReadError(dir + "/" + name);
        EXPECT_NE(why.find(dir + "/" + name), std::string::npos) << why;
        EXPECT_NE(why.find(expect), std::string::npos) << name << ": " << why;
    };
    const Nifti2Builder good = rampImage();

    std::vector<char> shortHeader = good.build();
    shortHeader.resize(400);
    check("header.nii", shortHeader, "truncated: NIfTI-2 header");

    std::vector<char> shortData = good.build();
    shortData.resize(shortData.size() - 1);
    check("data.nii", shortData, "truncated: voxel data");

    std::vector<char> textMode = good.build();
    textMode[8] = '\n';
    check("textmode.nii", textMode, "magic is damaged");

    std::vector<char> pair = good.build();
    std::memcpy(pair.data() + 4, "ni2\0", 4);
    check("pair.nii", pair, ".hdr/.img pair");

    Nifti2Builder wide = good;
    wide.dim[1] = std::int64_t(1) << 40;
    check("wide.nii", wide.build(), "dim[1] = 1099511627776 is too large");

    Nifti2Builder negative = good;
    negative.dim[3] = -2;
    check("negative.nii", negative.build(), "dim[3] = -2 is not positive");

    Nifti2Builder huge = good;
    huge.dim[1] = huge.dim[2] = huge.dim[3] = 2000000;
    check("huge.nii", huge.build(), "exceeds the limit");

    Nifti2Builder rank = good;
    rank.dim[0] = 9;
    check("rank.nii", rank.build(), "invalid dim[0] = 9");

    Nifti2Builder offset = good;
    offset.voxOffset = 100;
    check("offset.nii", offset.build(), "invalid vox_offset");

    Nifti2Builder complex = good;
    complex.datatype = 1792;
    complex.bitpix = 128;
    check("complex.nii", complex.build(), "unsupported NIfTI datatype complex128");
}

}  // namespace
}  // namespace volren::test
