// DICOM series loader (GDCM): the shared CT subset (expected values from its MANIFEST and an
// independent byte-level parse), sorting by position, several series, synthetic series
// written by a minimal DICOM writer below, and bad series that must fail with file and reason.
#include "GdcmProbe.h"
#include "TestData.h"

#include <volume_model/LengthUnit.h>
#include <volume_model/LoadProgress.h>
#include <volume_model/ReadVolume.h>

#include <osg/Matrixd>
#include <osg/ValueObject>
#include <osgDB/Options>
#include <osgDB/ReadFile>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

namespace volren::test {
namespace {

namespace fs = std::filesystem;

const char* const pancreasDir = "dicom/pancreas_ct_subset";


/// One slice of a synthetic single-frame DICOM file (explicit VR little endian, uncompressed).
struct SliceSpec
{
    std::string seriesUid = "1.2.3.4.1";
    int instance = 1;
    osg::Vec3d position;
    std::string orientation = "1\\0\\0\\0\\1\\0";
    std::string pixelSpacing = "0.5\\0.25";  // row spacing (y) \ column spacing (x)
    int rows = 2, columns = 3;
    int bits = 16;
    bool isSigned = false;
    std::string slope = "1", intercept = "0";
    std::vector<int> values;  // rows*columns, row by row
};

/// Writes data elements of explicit VR little endian, with even-length values.
class ElementWriter
{
public:
    void add(std::uint16_t group, std::uint16_t element, const char vr[3], std::string value)
    {
        if (value.size() % 2) value += (std::strcmp(vr, "UI") == 0 || std::strcmp(vr, "OB") == 0) ? '\0' : ' ';
        put16(group), put16(element);
        bytes.append(vr, 2);
        if (!std::strcmp(vr, "OB") || !std::strcmp(vr, "OW")) {
            put16(0);
            put32(std::uint32_t(value.size()));
        } else {
            put16(std::uint16_t(value.size()));
        }
        bytes += value;
    }
    void addUS(std::uint16_t group, std::uint16_t element, std::uint16_t v)
    {
        add(group, element, "US", std::string(reinterpret_cast<const char*>(&v), 2));
    }
    std::string bytes;

private:
    void put16(std::uint16_t v) { bytes.append(reinterpret_cast<const char*>(&v), 2); }
    void put32(std::uint32_t v) { bytes.append(reinterpret_cast<const char*>(&v), 4); }
};

void writeSlice(const std::string& path, const SliceSpec& s)
{
    const std::string sopClass = "1.2.840.10008.5.1.4.1.1.2";
    const std::string sopInstance = s.seriesUid + "." + std::to_string(s.instance);
    ElementWriter meta;
    meta.add(0x0002, 0x0001, "OB", std::string("\0\1", 2));
    meta.add(0x0002, 0x0002, "UI", sopClass);
    meta.add(0x0002, 0x0003, "UI", sopInstance);
    meta.add(0x0002, 0x0010, "UI", "1.2.840.10008.1.2.1");
    ElementWriter groupLength;
    const std::uint32_t metaLength = std::uint32_t(meta.bytes.size());
    groupLength.add(0x0002, 0x0000, "UL", std::string(reinterpret_cast<const char*>(&metaLength), 4));

    auto ds = [](double v) { std::ostringstream o; o << v; return o.str(); };
    ElementWriter data;
    data.add(0x0008, 0x0016, "UI", sopClass);
    data.add(0x0008, 0x0018, "UI", sopInstance);
    data.add(0x0008, 0x0060, "CS", "CT");
    data.add(0x0020, 0x000d, "UI", "1.2.3.4");
    data.add(0x0020, 0x000e, "UI", s.seriesUid);
    data.add(0x0020, 0x0013, "IS", std::to_string(s.instance));
    data.add(0x0020, 0x0032, "DS", ds(s.position.x()) + "\\" + ds(s.position.y()) + "\\" + ds(s.position.z()));
    data.add(0x0020, 0x0037, "DS", s.orientation);
    data.addUS(0x0028, 0x0002, 1);
    data.add(0x0028, 0x0004, "CS", "MONOCHROME2");
    data.addUS(0x0028, 0x0010, std::uint16_t(s.rows));
    data.addUS(0x0028, 0x0011, std::uint16_t(s.columns));
    data.add(0x0028, 0x0030, "DS", s.pixelSpacing);
    data.addUS(0x0028, 0x0100, std::uint16_t(s.bits));
    data.addUS(0x0028, 0x0101, std::uint16_t(s.bits));
    data.addUS(0x0028, 0x0102, std::uint16_t(s.bits - 1));
    data.addUS(0x0028, 0x0103, s.isSigned ? 1 : 0);
    data.add(0x0028, 0x1052, "DS", s.intercept);
    data.add(0x0028, 0x1053, "DS", s.slope);
    std::string pixels;
    for (int v : s.values) {
        if (s.bits == 8) pixels += char(v);
        else pixels.append(reinterpret_cast<const char*>(&v), 2);  // little endian low 16 bits
    }
    data.add(0x7fe0, 0x0010, s.bits == 8 ? "OB" : "OW", pixels);

    std::ofstream out(path, std::ios::binary);
    out << std::string(128, '\0') << "DICM" << groupLength.bytes << meta.bytes << data.bytes;
}

/// A series of `count` 3x2 slices 2.5 apart along z, written in reverse name order.
std::vector<SliceSpec> syntheticSeries(int count, const std::string& uid = "1.2.3.4.1")
{
    std::vector<SliceSpec> slices;
    for (int k = 0; k < count; ++k) {
        SliceSpec s;
        s.seriesUid = uid;
        s.instance = k + 1;
        s.position.set(-10, 20, 100 + 2.5 * k);
        for (int i = 0; i < 6; ++i) s.values.push_back(100 * k + i);
        slices.push_back(s);
    }
    return slices;
}

void writeSeries(const std::string& dir, const std::vector<SliceSpec>& slices, const std::string& prefix = "s")
{
    fs::create_directories(dir);
    for (std::size_t k = 0; k < slices.size(); ++k)
        writeSlice(dir + "/" + prefix + std::to_string(slices.size() - k) + ".dcm", slices[k]);
}

TEST(DicomReader, ReadsPancreasCtSubsetAsInTheManifest)
{
    VOLREN_REQUIRE_SHARED_DATA();
    const std::string dir = sharedData(pancreasDir);
    osg::ref_ptr<Volume> v = readVolumeFile(dir);
    EXPECT_EQ(v->dims(), osg::Vec3i(512, 512, 24));
    EXPECT_EQ(v->type(), VoxelType::UInt16);
    EXPECT_NEAR(v->spacing().x(), 1.07421875, 1e-9);
    EXPECT_NEAR(v->spacing().y(), 1.07421875, 1e-9);
    EXPECT_NEAR(v->spacing().z(), 3.0, 1e-6);
    EXPECT_EQ(lengthUnitOf(*v), "mm");
    EXPECT_EQ(v->rescaleSlope(), 1.0);
    EXPECT_EQ(v->rescaleIntercept(), -1000.0);
    EXPECT_EQ(v->sourceFile, dir);

    // Independent statistics: a python3 script (struct module only, no DICOM library) walked
    // each file's data elements (explicit VR meta group, implicit VR LE data set), took the
    // 524288-byte PixelData as little-endian uint16, ordered the files by the z of
    // ImagePositionPatient (IOP is 1\0\0\0\1\0) and summed; slice k=0 (1-079.dcm, the lowest
    // z) was cross-checked with `gdcmraw` (sum 74531581, voxel (256,256) = 1110).
    double sum = 0.0, sum0 = 0.0;
    const std::size_t slice = 512 * 512;
    for (std::size_t i = 0; i < v->voxelCount(); ++i) {
        const double s = v->storedValue(i);
        sum += s;
        if (i < slice) sum0 += s;
    }
    EXPECT_EQ(sum, 1907837949.0);
    EXPECT_EQ(sum0, 74531581.0);
    EXPECT_EQ(v->valueRange(), std::make_pair(0.0 - 1000.0, 2365.0 - 1000.0));
    EXPECT_EQ(v->value(256, 256, 0), 1110.0 - 1000.0);
    EXPECT_EQ(v->value(100, 300, 12), 1035.0 - 1000.0);
    EXPECT_EQ(v->value(300, 200, 5), 1011.0 - 1000.0);

    osg::Matrixd toWorld;
    ASSERT_TRUE(v->getUserValue("voxelToWorld", toWorld));
    const osg::Vec3d origin = osg::Vec3d(0, 0, 0) * toWorld, last = osg::Vec3d(511, 511, 23) * toWorld;
    EXPECT_NEAR((origin - osg::Vec3d(-275, -178.1, 250.91)).length(), 0.0, 1e-6);
    EXPECT_NEAR(last.z(), 319.91, 1e-6);
    EXPECT_NEAR(last.x(), -275 + 511 * 1.07421875, 1e-6);
}

TEST(DicomReader, OneSliceFileReadsItsWholeSeries)
{
    VOLREN_REQUIRE_SHARED_DATA();
    const std::string dir = sharedData(pancreasDir);
    osg::ref_ptr<Volume> whole = readVolumeFile(dir);
    osg::ref_ptr<Volume> v = readVolumeFile(dir + "/1-060.dcm");
    EXPECT_EQ(v->dims(), osg::Vec3i(512, 512, 24));
    ASSERT_EQ(v->byteSize(), whole->byteSize());
    EXPECT_EQ(std::memcmp(v->data(), whole->data(), v->byteSize()), 0);
}

TEST(DicomReader, ShuffledFileNamesStillSortByPosition)
{
    VOLREN_REQUIRE_SHARED_DATA();
    const std::string source = sharedData(pancreasDir);
    const std::string dir = tempDirectory() + "/shuffled";
    fs::create_directories(dir);
    for (int n = 56; n <= 79; ++n) {
        char name[16];
        std::snprintf(name, sizeof(name), "1-%03d.dcm", n);
        // A fixed permutation unrelated to position: 7 * n mod 24 (7 and 24 are coprime).
        fs::copy_file(source + "/" + name, dir + "/img" + std::to_string((7 * n) % 24) + ".dcm");
    }
    osg::ref_ptr<Volume> original = readVolumeFile(source);
    osg::ref_ptr<Volume> shuffled = readVolumeFile(dir);
    EXPECT_EQ(shuffled->dims(), osg::Vec3i(512, 512, 24));
    EXPECT_NEAR(shuffled->spacing().z(), 3.0, 1e-6);
    ASSERT_EQ(shuffled->byteSize(), original->byteSize());
    EXPECT_EQ(std::memcmp(shuffled->data(), original->data(), original->byteSize()), 0);
    EXPECT_EQ(shuffled->value(256, 256, 0), 110.0);  // 1-079.dcm, the lowest slice
}

TEST(DicomReader, StockOsgDbPathReachesTheVolrenReader)
{
    VOLREN_REQUIRE_SHARED_DATA();
    // OSG's registry maps .dcm to osgdb_dicom: volren's plugin must be the one found.
    registerPluginPath();
    const std::string slice = sharedData(pancreasDir) + "/1-060.dcm";
    osg::ref_ptr<osg::Object> object = osgDB::readRefObjectFile(slice);
    auto* v = dynamic_cast<Volume*>(object.get());
    ASSERT_NE(v, nullptr) << "osgDB::readRefObjectFile did not give a volren::Volume";
    EXPECT_EQ(v->dims(), osg::Vec3i(512, 512, 24));
    EXPECT_TRUE(osgDB::readRefNodeFile(slice).valid()) << "a series read as a node gets the default scene";
    EXPECT_TRUE(isVolumeFile(slice));
}

TEST(DicomReader, ProgressIsReportedPerSliceAndCancellationStops)
{
    VOLREN_REQUIRE_SHARED_DATA();
    const std::string dir = sharedData(pancreasDir);
    std::vector<double> seen;
    const LoadProgress record = [&seen](double f) {
        seen.push_back(f);
        return true;
    };
    readVolumeFile(dir, withLoadProgress(nullptr, &record).get());
    ASSERT_EQ(seen.size(), 24u);
    EXPECT_DOUBLE_EQ(seen.back(), 1.0);
    EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));

    int calls = 0;
    const LoadProgress cancel = [&calls](double) { return ++calls < 3; };
    const std::string why = expectReadError(dir, withLoadProgress(nullptr, &cancel).get());
    EXPECT_NE(why.find("cancelled"), std::string::npos) << why;
    EXPECT_EQ(calls, 3);
}

TEST(DicomReader, MissingSliceIsReportedAsNonUniformSpacing)
{
    VOLREN_REQUIRE_SHARED_DATA();
    const std::string source = sharedData(pancreasDir);
    const std::string dir = tempDirectory() + "/gap";
    fs::create_directories(dir);
    for (int n = 56; n <= 79; ++n) {
        if (n == 70) continue;
        char name[16];
        std::snprintf(name, sizeof(name), "1-%03d.dcm", n);
        fs::copy_file(source + "/" + name, dir + "/" + name);
    }
    const std::string why = expectReadError(dir);
    EXPECT_NE(why.find(dir), std::string::npos) << why;
    EXPECT_NE(why.find("not uniform"), std::string::npos) << why;
}

TEST(DicomReader, CompressedTransferSyntaxDecodesToTheSameVoxels)
{
    VOLREN_REQUIRE_SHARED_DATA();
    if (std::system("gdcmconv --version >/dev/null 2>&1") != 0) GTEST_SKIP() << "gdcmconv (libgdcm-tools) is absent";
    const std::string source = sharedData(pancreasDir);
    const std::string dir = tempDirectory() + "/jpegls";
    fs::create_directories(dir);
    for (int n = 56; n <= 79; ++n) {
        char name[16];
        std::snprintf(name, sizeof(name), "1-%03d.dcm", n);
        const std::string command = "gdcmconv --jpegls '" + source + "/" + name + "' '" + dir + "/" + name + "'";
        ASSERT_EQ(std::system(command.c_str()), 0) << command;
    }
    osg::ref_ptr<Volume> original = readVolumeFile(source);
    osg::ref_ptr<Volume> decoded = readVolumeFile(dir);
    ASSERT_EQ(decoded->byteSize(), original->byteSize());
    EXPECT_EQ(std::memcmp(decoded->data(), original->data(), original->byteSize()), 0);  // JPEG-LS is lossless
}

TEST(DicomReader, SyntheticSignedCoronalSeriesReadsExactly)
{
    const std::string dir = tempDirectory() + "/coronal";
    std::vector<SliceSpec> slices = syntheticSeries(4);
    for (std::size_t k = 0; k < slices.size(); ++k) {
        SliceSpec& s = slices[k];
        s.orientation = "1\\0\\0\\0\\0\\-1";           // rows along x, columns along -z: normal +y
        s.position.set(5, -3.0 + 1.25 * double(k), 7);  // slices 1.25 apart along y
        s.isSigned = true;
        s.slope = "2";
        s.intercept = "-5";
        for (int i = 0; i < 6; ++i) s.values[i] = -300 + 100 * int(k) + i;
    }
    writeSeries(dir, slices);
    osg::ref_ptr<Volume> v = readVolumeFile(dir);
    EXPECT_EQ(v->dims(), osg::Vec3i(3, 2, 4));
    EXPECT_EQ(v->type(), VoxelType::Int16);
    EXPECT_EQ(v->spacing(), osg::Vec3d(0.25, 0.5, 1.25));
    EXPECT_EQ(v->rescaleSlope(), 2.0);
    EXPECT_EQ(v->rescaleIntercept(), -5.0);
    for (int k = 0; k < 4; ++k)
        for (int i = 0; i < 6; ++i) EXPECT_EQ(v->value(i % 3, i / 3, k), (-300 + 100 * k + i) * 2.0 - 5.0) << k << " " << i;
    osg::Matrixd toWorld;
    ASSERT_TRUE(v->getUserValue("voxelToWorld", toWorld));
    EXPECT_NEAR((osg::Vec3d(1, 1, 2) * toWorld - osg::Vec3d(5 + 0.25, -3 + 2.5, 7 - 0.5)).length(), 0.0, 1e-9);
}

TEST(DicomReader, EightBitAndPerSliceRescaleSeries)
{
    const std::string dir = tempDirectory();
    std::vector<SliceSpec> bytes = syntheticSeries(3);
    for (SliceSpec& s : bytes) s.bits = 8;
    writeSeries(dir + "/u8", bytes);
    osg::ref_ptr<Volume> v = readVolumeFile(dir + "/u8");
    EXPECT_EQ(v->type(), VoxelType::UInt8);
    EXPECT_EQ(v->value(2, 1, 2), 205.0);

    std::vector<SliceSpec> mixed = syntheticSeries(3);
    mixed[1].slope = "0.5";
    mixed[2].intercept = "10";
    writeSeries(dir + "/mixed", mixed);
    v = readVolumeFile(dir + "/mixed");
    EXPECT_EQ(v->type(), VoxelType::Float32);
    EXPECT_EQ(v->value(1, 0, 0), 1.0);
    EXPECT_EQ(v->value(1, 0, 1), 101 * 0.5);
    EXPECT_EQ(v->value(1, 0, 2), 201 + 10.0);
}

TEST(DicomReader, SeveralSeriesTakeTheLargestOrTheOneAsked)
{
    const std::string dir = tempDirectory() + "/two";
    writeSeries(dir, syntheticSeries(3, "1.2.3.4.10"), "a");
    writeSeries(dir, syntheticSeries(5, "1.2.3.4.20"), "b");
    std::ofstream(dir + "/notes.txt") << "not DICOM";
    EXPECT_EQ(readVolumeFile(dir)->dims().z(), 5);
    osg::ref_ptr<osgDB::Options> options = new osgDB::Options("DicomSeries=1.2.3.4.10");
    EXPECT_EQ(readVolumeFile(dir, options.get())->dims().z(), 3);
    EXPECT_EQ(readVolumeFile(dir + "/a1.dcm")->dims().z(), 3);  // a slice file picks its own series
    options = new osgDB::Options("DicomSeries=9.9.9");
    const std::string why = expectReadError(dir, options.get());
    EXPECT_NE(why.find("no DICOM series 9.9.9"), std::string::npos) << why;
}

TEST(DicomReader, BadSeriesAreRejectedWithFileAndReason)
{
    const std::string root = tempDirectory();
    auto check = [](const std::string& path, const std::string& expect) {
        const std::string why = expectReadError(path);
        EXPECT_NE(why.find(path), std::string::npos) << why;
        EXPECT_NE(why.find(expect), std::string::npos) << path << ": " << why;
    };

    std::vector<SliceSpec> mixed = syntheticSeries(3);
    mixed[1].columns = 2;
    mixed[1].values.resize(4);
    writeSeries(root + "/mixed", mixed);
    check(root + "/mixed", "mixed slice sizes");

    std::vector<SliceSpec> duplicate = syntheticSeries(3);
    duplicate[2].position = duplicate[1].position;
    writeSeries(root + "/duplicate", duplicate);
    check(root + "/duplicate", "same position");

    std::vector<SliceSpec> shortPixels = syntheticSeries(2);
    shortPixels[1].values.resize(4);  // PixelData shorter than rows x columns
    writeSeries(root + "/short", shortPixels);
    check(root + "/short", "s1.dcm: truncated: pixel data needs 12 bytes, the file holds 8");

    std::vector<SliceSpec> zeroRows = syntheticSeries(2);
    for (SliceSpec& s : zeroRows) s.rows = 0, s.values.clear();
    writeSeries(root + "/zero", zeroRows);
    check(root + "/zero", "image size 3x0 (Columns x Rows) is not positive");

    writeSeries(root + "/cut", syntheticSeries(2));
    fs::resize_file(root + "/cut/s1.dcm", fs::file_size(root + "/cut/s1.dcm") - 5);
    check(root + "/cut", "s1.dcm: malformed DICOM file: element (7fe0,0010) at byte");

    // GDCM 3.0 aborts the process on this fuzzer-found file (an element length past the end of
    // the file); the structure check refuses it first.
    const std::string known = std::string(VOLREN_SOURCE_DIR) + "/tests/fuzz/known/dcm-gdcm-ReadCompat-assert.dcm";
    fs::create_directories(root + "/gdcm-abort");
    fs::copy_file(known, root + "/gdcm-abort/slice.dcm");
    check(root + "/gdcm-abort/slice.dcm", "malformed DICOM file: element (0020,000d) at byte 340 claims 27678 bytes; 246 are left");
    check(root + "/gdcm-abort", "slice.dcm: malformed DICOM file: element (0020,000d)");
    // A bare data set (no Part 10 preamble) whose first element is cut short: GDCM 3.0 aborts in
    // ExplicitDataElement::ReadPreValue; it is not DICOM to volren, and skipped in a folder.
    const std::string bare = std::string(VOLREN_SOURCE_DIR) + "/tests/fuzz/known/dcm-gdcm-ReadPreValue-assert.dcm";
    fs::create_directories(root + "/gdcm-abort2");
    fs::copy_file(bare, root + "/gdcm-abort2/slice.dcm");
    check(root + "/gdcm-abort2/slice.dcm", "not a DICOM file: truncated");
    check(root + "/gdcm-abort2", "no DICOM files");
    // A sequence in the file meta group: GDCM 3.0 aborts in ReadExplicitDataElement.
    const std::string metaSq = std::string(VOLREN_SOURCE_DIR) + "/tests/fuzz/known/dcm-gdcm-meta-SQ-assert.dcm";
    fs::create_directories(root + "/gdcm-abort3");
    fs::copy_file(metaSq, root + "/gdcm-abort3/slice.dcm");
    check(root + "/gdcm-abort3/slice.dcm", "file meta information: (0002,0001) is a sequence");
    // An implicit-VR meta group made GDCM abort (the child-process probe caught it first); its
    // "VR" is no VR, so the structure check now refuses it.
    const std::string implicitMeta = std::string(VOLREN_SOURCE_DIR) + "/tests/fuzz/known/dcm-gdcm-ReadImplicitDataElement-assert.dcm";
    fs::create_directories(root + "/gdcm-abort4");
    fs::copy_file(implicitMeta, root + "/gdcm-abort4/slice.dcm");
    check(root + "/gdcm-abort4/slice.dcm", "file meta information: element (0002,0004) at byte 132 has an unknown VR");
    // One that passed GDCM's scan but aborted its image reader (a bad VR in the meta group).
    const std::string imageAbort = std::string(VOLREN_SOURCE_DIR) + "/tests/fuzz/known/dcm-gdcm-ImageReader-assert.dcm";
    fs::create_directories(root + "/gdcm-abort5");
    fs::copy_file(imageAbort, root + "/gdcm-abort5/slice.dcm");
    check(root + "/gdcm-abort5", "slice.dcm: malformed DICOM file: file meta information: element (0002,0010) at byte 230 has an unknown VR");
    // Unknown VRs ("UW", "UQ"): GDCM misread the lengths and grew to 2.2 GB.
    for (const char* name : {"dcm-gdcm-memory-growth.dcm", "dcm-gdcm-unknown-VR-memory.dcm"}) {
        const std::string dir = root + "/" + name + ".d";
        fs::create_directories(dir);
        fs::copy_file(std::string(VOLREN_SOURCE_DIR) + "/tests/fuzz/known/" + name, dir + "/slice.dcm");
        check(dir + "/slice.dcm", "malformed DICOM file: element (0028,0103) at byte 560 has an unknown VR");
    }
    // SamplesPerPixel 2 made GDCM's image reader abort (the child-process probe turned that into
    // an error); its seed had (0018,0050) after group 0028, out of order, which is refused now.
    fs::create_directories(root + "/gdcm-abort6");
    fs::copy_file(std::string(VOLREN_SOURCE_DIR) + "/tests/fuzz/known/dcm-gdcm-SamplesPerPixel-assert.dcm",
                  root + "/gdcm-abort6/slice.dcm");
    check(root + "/gdcm-abort6/slice.dcm", "element (0018,0050) at byte 570 is out of order");
    // No file meta group after "DICM" (and tags out of order): GDCM grew to 2.0 GB on it.
    fs::create_directories(root + "/gdcm-memory3");
    fs::copy_file(std::string(VOLREN_SOURCE_DIR) + "/tests/fuzz/known/dcm-gdcm-memory-open.dcm",
                  root + "/gdcm-memory3/slice.dcm");
    check(root + "/gdcm-memory3/slice.dcm", "malformed DICOM file: no file meta information (group 0002)");
    // Tags out of order in the data set.
    std::ifstream ordered(std::string(VOLREN_SOURCE_DIR) + "/tests/fuzz/corpus/dcm/uint8.dcm", std::ios::binary);
    std::string swapped((std::istreambuf_iterator<char>(ordered)), std::istreambuf_iterator<char>());
    const std::size_t modality = swapped.find(std::string("\x08\x00\x60\x00", 4));
    ASSERT_NE(modality, std::string::npos);
    swapped[modality + 2] = '\x00';  // (0008,0060) becomes (0008,0000), after (0008,0018)
    fs::create_directories(root + "/out-of-order");
    writeFile(root + "/out-of-order/slice.dcm", swapped);
    check(root + "/out-of-order/slice.dcm", "is out of order (tags must ascend)");
    // Bits Allocated and Bits Stored disagree: GDCM's codec asserts while decoding; the probe's
    // child decodes first and dies instead.
    fs::create_directories(root + "/gdcm-codec");
    fs::copy_file(std::string(VOLREN_SOURCE_DIR) + "/tests/fuzz/known/dcm-gdcm-codec-assert.dcm", root + "/gdcm-codec/slice.dcm");
    check(root + "/gdcm-codec/slice.dcm", "slice.dcm: GDCM aborted reading it");
    // No Pixel Data element: not an image; refused when named, skipped in a folder, before GDCM
    // (which grew to 2.2 GB looking for it) reads it.
    std::ifstream seed(std::string(VOLREN_SOURCE_DIR) + "/tests/fuzz/corpus/dcm/uint8.dcm", std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(seed)), std::istreambuf_iterator<char>());
    const std::size_t pixelTag = bytes.find(std::string("\xe0\x7f\x10\x00", 4));
    ASSERT_NE(pixelTag, std::string::npos);
    bytes[pixelTag + 3] = '\x09';  // (7FE0,0910): a sound element, but no pixel data
    fs::create_directories(root + "/no-pixels");
    writeFile(root + "/no-pixels/slice.dcm", bytes);
    check(root + "/no-pixels/slice.dcm", "without pixel data (7FE0,0010)");
    check(root + "/no-pixels", "no DICOM files");

    fs::create_directories(root + "/empty");
    check(root + "/empty", "empty directory (expected TIFF, 2D image or DICOM slices)");
    std::ofstream(root + "/junk.dcm") << "definitely not a DICOM file";
    check(root + "/junk.dcm", "not a DICOM file");
    check(root + "/nope.dcm", "no such file");
}

TEST(DicomReader, AnAbortWhileProbingAFileBecomesAnErrorNamingIt)
{
    // What the child-process probe is for: GDCM aborting (here: a step that aborts on one file)
    // ends the child, not this process, and names the file it was reading.
    const std::vector<std::string> files = {"a.dcm", "b.dcm", "c.dcm"};
    const std::string message = dicom::probeInChild(files, [](const std::string& f) {
        if (f == "b.dcm") std::abort();
    });
    EXPECT_EQ(message.rfind("b.dcm: GDCM aborted reading it", 0), 0u) << message;
    EXPECT_EQ(dicom::probeInChild(files, [](const std::string&) {}), "");
    EXPECT_EQ(dicom::probeInChild(files, [](const std::string&) { throw std::runtime_error("ordinary error"); }), "");
}

}  // namespace
}  // namespace volren::test
