// NRRD reader and writer: the shared datasets (expected values from MANIFEST.md and from an
// independent decode of the raw bytes), write→read round trips, and bad files that must fail
// with the file name and the reason.
#include "TestData.h"

#include <volume_model/LoadProgress.h>
#include <volume_model/ReadVolume.h>

#include <osgDB/ReadFile>
#include <osgDB/WriteFile>
#include <gtest/gtest.h>
#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>

namespace volren::test {
namespace {

std::string gzipped(const std::string& bytes)
{
    z_stream zs{};
    deflateInit2(&zs, 6, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY);
    std::string out(deflateBound(&zs, uLong(bytes.size())) + 64, '\0');
    zs.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes.data()));
    zs.avail_in = uInt(bytes.size());
    zs.next_out = reinterpret_cast<Bytef*>(&out[0]);
    zs.avail_out = uInt(out.size());
    deflate(&zs, Z_FINISH);
    out.resize(zs.total_out);
    deflateEnd(&zs);
    return out;
}

/// int16 little-endian bytes 0, 1, ..., n-1 (times `scale`).
std::string int16Ramp(int n, int scale = 1)
{
    std::string bytes;
    for (int i = 0; i < n; ++i) {
        const std::int16_t v = std::int16_t(i * scale);
        bytes.append(reinterpret_cast<const char*>(&v), 2);
    }
    return bytes;
}


/// Sum, min, max and the order-sensitive sum of (i % 251) * value over all stored values.
struct Stats
{
    double sum = 0, lo = std::numeric_limits<double>::max(), hi = -std::numeric_limits<double>::max(), weighted = 0;
};
Stats statsOf(const Volume& v)
{
    Stats s;
    for (std::size_t i = 0; i < v.totalVoxelCount(); ++i) {
        const double x = v.storedValue(i);
        s.sum += x;
        s.lo = std::min(s.lo, x);
        s.hi = std::max(s.hi, x);
        s.weighted += double(i % 251) * x;
    }
    return s;
}

const std::string smallHeader = "NRRD0004\ntype: short\ndimension: 3\nsizes: 2 3 4\nspacings: 1 1 1\nendian: little\n";

TEST(NrrdReader, ReadsBaselineVolumeAsInTheManifest)
{
    VOLREN_REQUIRE_SHARED_DATA();
    const std::string path = sharedData("mri/BaselineVolume.nrrd");
    osg::ref_ptr<Volume> v = readVolumeFile(path);
    EXPECT_EQ(v->dims(), osg::Vec3i(256, 256, 51));
    EXPECT_EQ(v->type(), VoxelType::Int16);
    EXPECT_EQ(v->channels(), 1);
    EXPECT_NEAR(v->spacing().x(), 1.0, 1e-12);
    EXPECT_NEAR(v->spacing().y(), 1.0, 1e-12);
    EXPECT_NEAR(v->spacing().z(), 2.6, 1e-12);
    EXPECT_EQ(v->sourceFile, path);
    // Independent: python3 -c "import gzip,array; d=open('mri/BaselineVolume.nrrd','rb').read();
    //   a=array.array('h'); a.frombytes(gzip.decompress(d[d.index(b'\n\n')+2:]));
    //   print(sum(a), min(a), max(a), sum((i%251)*x for i,x in enumerate(a)))"
    // (payload sha256 e742d9e37ad834c584083566c9229f516ae362f487ff3276e8266d33332e83d4).
    const Stats s = statsOf(*v);
    EXPECT_EQ(s.sum, 931047237.0);
    EXPECT_EQ(s.lo, 0.0);
    EXPECT_EQ(s.hi, 18197.0);
    EXPECT_EQ(s.weighted, 116805063332.0);
}

TEST(NrrdReader, ReadsHeadsqDetachedSliceFilesAsInTheManifest)
{
    VOLREN_REQUIRE_SHARED_DATA();
    osg::ref_ptr<Volume> v = readVolumeFile(sharedData("ct/headsq/quarter.nhdr"));
    EXPECT_EQ(v->dims(), osg::Vec3i(64, 64, 93));
    EXPECT_EQ(v->type(), VoxelType::Int16);
    EXPECT_EQ(v->channels(), 1);
    EXPECT_NEAR(v->spacing().x(), 3.2, 1e-12);
    EXPECT_NEAR(v->spacing().y(), 3.2, 1e-12);
    EXPECT_NEAR(v->spacing().z(), 1.5, 1e-12);
    // Independent: python3 -c "import array; a=array.array('h'); a.frombytes(b''.join(
    //   open('ct/headsq/quarter.%d'%k,'rb').read() for k in range(1,94)));
    //   print(sum(a), min(a), max(a), sum((i%251)*x for i,x in enumerate(a)))"
    // (payload sha256 74011a3339b1a56ca85c8c6920a46c0f80bddcc660bd9f78512888e06c496ce3).
    const Stats s = statsOf(*v);
    EXPECT_EQ(s.sum, 193392317.0);
    EXPECT_EQ(s.lo, 0.0);
    EXPECT_EQ(s.hi, 3926.0);
    EXPECT_EQ(s.weighted, 24186023061.0);
}

TEST(NrrdReader, StockOsgReadFunctionsFindBothExtensions)
{
    VOLREN_REQUIRE_SHARED_DATA();
    registerPluginPath();
    for (const char* file : {"mri/BaselineVolume.nrrd", "ct/headsq/quarter.nhdr"}) {
        osg::ref_ptr<osg::Object> object = osgDB::readRefObjectFile(sharedData(file));
        ASSERT_NE(dynamic_cast<Volume*>(object.get()), nullptr) << file;
        EXPECT_TRUE(osgDB::readRefNodeFile(sharedData(file)).valid()) << file << ": a bare volume read as a node gets the default scene";
    }
}

osg::ref_ptr<Volume> patternVolume(VoxelType type, int channels)
{
    osg::ref_ptr<Volume> v = new Volume;
    v->allocate(type, osg::Vec3i(5, 4, 3), channels);
    for (int c = 0; c < channels; ++c) {
        std::uint8_t* p = v->block(c);
        for (std::size_t i = 0; i < v->voxelCount(); ++i) {
            const double x = double(i * 37 % 97) - (type == VoxelType::Int8 || type == VoxelType::Int16 ? 40.0 : 0.0) + 100.0 * c;
            switch (type) {
            case VoxelType::UInt8: p[i] = std::uint8_t(x); break;
            case VoxelType::Int8: p[i] = std::uint8_t(std::int8_t(x)); break;
            case VoxelType::UInt16: { const std::uint16_t s = std::uint16_t(x * 600); std::memcpy(p + 2 * i, &s, 2); break; }
            case VoxelType::Int16: { const std::int16_t s = std::int16_t(x * 300); std::memcpy(p + 2 * i, &s, 2); break; }
            case VoxelType::Float32: { const float f = float(x) * 0.37f - 3.0f; std::memcpy(p + 4 * i, &f, 4); break; }
            }
        }
    }
    v->setSpacing(osg::Vec3d(0.1, 0.7 / 3.0, 2.6));
    v->dirty();
    return v;
}

struct RoundTrip
{
    VoxelType type;
    int channels;
    const char* encoding;
};

class NrrdRoundTrip : public ::testing::TestWithParam<RoundTrip>
{
};

TEST_P(NrrdRoundTrip, WriteThenReadIsVoxelIdentical)
{
    registerPluginPath();
    const RoundTrip p = GetParam();
    osg::ref_ptr<Volume> original = patternVolume(p.type, p.channels);
    const std::string path = tempDirectory() + "/out.nrrd";
    osg::ref_ptr<osgDB::Options> options = new osgDB::Options(std::string("encoding=") + p.encoding);
    ASSERT_TRUE(osgDB::writeObjectFile(*original, path, options.get()));
    osg::ref_ptr<Volume> back = readVolumeFile(path);
    EXPECT_EQ(back->type(), original->type());
    EXPECT_EQ(back->dims(), original->dims());
    EXPECT_EQ(back->channels(), original->channels());
    EXPECT_EQ(back->spacing(), original->spacing());  // written with 17 digits: exact
    ASSERT_EQ(back->byteSize(), original->byteSize());
    EXPECT_EQ(std::memcmp(back->data(), original->data(), original->byteSize()), 0);
    std::ifstream in(path, std::ios::binary);
    std::string text((std::istreambuf_iterator<char>(in)), {});
    EXPECT_NE(text.find(std::string("encoding: ") + p.encoding), std::string::npos);
}

INSTANTIATE_TEST_SUITE_P(NrrdWriter, NrrdRoundTrip,
                         ::testing::Values(RoundTrip{VoxelType::UInt8, 1, "gzip"}, RoundTrip{VoxelType::Int16, 1, "gzip"},
                                           RoundTrip{VoxelType::UInt16, 1, "raw"}, RoundTrip{VoxelType::Float32, 1, "gzip"},
                                           RoundTrip{VoxelType::Int8, 1, "raw"}, RoundTrip{VoxelType::UInt16, 2, "gzip"},
                                           RoundTrip{VoxelType::Float32, 2, "raw"}),
                         [](const ::testing::TestParamInfo<RoundTrip>& info) {
                             return std::string(voxelTypeName(info.param.type)) + "_" + std::to_string(info.param.channels) +
                                    "ch_" + info.param.encoding;
                         });

TEST(NrrdWriter, KeepsTheValueRescale)
{
    registerPluginPath();
    osg::ref_ptr<Volume> v = patternVolume(VoxelType::Int16, 1);
    v->setRescale(0.25, -1024.0);
    const std::string dir = tempDirectory();
    ASSERT_TRUE(osgDB::writeObjectFile(*v, dir + "/r.nrrd"));
    osg::ref_ptr<Volume> back = readVolumeFile(dir + "/r.nrrd");
    EXPECT_EQ(back->rescaleSlope(), 0.25);
    EXPECT_EQ(back->rescaleIntercept(), -1024.0);
}

TEST(NrrdReader, ReadsBigEndianGzipAndListedDataFiles)
{
    const std::string dir = tempDirectory();
    std::string big = int16Ramp(24, -300);
    for (std::size_t i = 0; i < big.size(); i += 2) std::swap(big[i], big[i + 1]);
    writeFile(dir + "/big.nrrd", "NRRD0004\ntype: short\ndimension: 3\nsizes: 2 3 4\nspacings: 1 1 1\nendian: big\nencoding: gzip\n\n" + gzipped(big));
    const std::string ramp = int16Ramp(24, -300);
    writeFile(dir + "/a.raw", ramp.substr(0, 24));
    writeFile(dir + "/b.raw", ramp.substr(24));
    writeFile(dir + "/list.nhdr", smallHeader + "encoding: raw\ndata file: LIST\na.raw\nb.raw\n");
    writeFile(dir + "/s1.raw", ramp.substr(0, 16));
    writeFile(dir + "/s3.raw", ramp.substr(16, 16));
    writeFile(dir + "/s5.raw", ramp.substr(32));
    writeFile(dir + "/pattern.nhdr", smallHeader + "encoding: raw\ndata file: s%d.raw 1 5 2\n");
    for (const char* name : {"/big.nrrd", "/list.nhdr", "/pattern.nhdr"}) {
        osg::ref_ptr<Volume> v = readVolumeFile(dir + name);
        ASSERT_EQ(v->dims(), osg::Vec3i(2, 3, 4)) << name;
        for (int i = 0; i < 24; ++i) ASSERT_EQ(v->value(std::size_t(i)), -300.0 * i) << name << " " << i;
    }
}

TEST(NrrdReader, FourDimensionalRgbBecomesChannelsAndSpacingComesFromDirections)
{
    const std::string dir = tempDirectory();
    std::string bytes;
    for (int i = 0; i < 8; ++i) bytes += {char(i), char(100 + i), char(200 + i / 2)};
    writeFile(dir + "/rgb.nrrd", "NRRD0005\ntype: uchar\ndimension: 4\nsizes: 3 2 2 2\nkinds: RGB-color domain domain domain\n"
                                 "space directions: none (0,0.5,0) (3,4,0) (0,0,2)\nspace origin: (1,2,3)\nencoding: raw\n\n" + bytes);
    osg::ref_ptr<Volume> v = readVolumeFile(dir + "/rgb.nrrd");
    EXPECT_EQ(v->channels(), 3);
    EXPECT_EQ(v->dims(), osg::Vec3i(2, 2, 2));
    EXPECT_EQ(v->spacing(), osg::Vec3d(0.5, 5.0, 2.0));
    for (int i = 0; i < 8; ++i) {
        EXPECT_EQ(v->block(0)[i], i);
        EXPECT_EQ(v->block(1)[i], 100 + i);
        EXPECT_EQ(v->block(2)[i], 200 + i / 2);
    }
}

TEST(NrrdReader, HeaderClaimingMoreThanTheFileHoldsIsRefusedBeforeAllocating)
{
    // Found by fuzz_nrrd: a 90-byte file whose sizes ask for 4 GiB of voxels was allocated for
    // before the reader found out that the data were missing; now the file size comes first.
    const std::string dir = tempDirectory();
    writeFile(dir + "/liar.nrrd", "NRRD0004\ntype: uchar\ndimension: 3\nsizes: 2048 2048 1024\nencoding: raw\n\n0123456789");
    const std::string why = expectReadError(dir + "/liar.nrrd");
    EXPECT_NE(why.find(dir + "/liar.nrrd: truncated: data file " + dir +
                       "/liar.nrrd holds 10 bytes of voxel data, the header needs 4294967296"), std::string::npos) << why;
}

TEST(NrrdReader, Int32BecomesExactFloatOrIsRefused)
{
    const std::string dir = tempDirectory();
    std::string bytes;
    for (std::int32_t x : {-16777216, 0, 5, 16777216, 7, 8, 9, 10}) bytes.append(reinterpret_cast<const char*>(&x), 4);
    const std::string header = "NRRD0004\ntype: int\ndimension: 3\nsizes: 2 2 2\nendian: little\nencoding: raw\n\n";
    writeFile(dir + "/ok.nrrd", header + bytes);
    osg::ref_ptr<Volume> v = readVolumeFile(dir + "/ok.nrrd");
    EXPECT_EQ(v->type(), VoxelType::Float32);
    EXPECT_EQ(v->value(std::size_t(0)), -16777216.0);
    EXPECT_EQ(v->value(std::size_t(3)), 16777216.0);
    const std::int32_t tooBig = 16777217;
    std::memcpy(&bytes[4], &tooBig, 4);
    writeFile(dir + "/big.nrrd", header + bytes);
    const std::string why = expectReadError(dir + "/big.nrrd");
    EXPECT_NE(why.find(dir + "/big.nrrd"), std::string::npos) << why;
    EXPECT_NE(why.find("int32 value 16777217 at voxel 1 does not fit float32 exactly"), std::string::npos) << why;
}

/// Writes `bytes` as `name` in a fresh folder and expects readVolumeFile to fail with a message
/// that names the file and contains `reason`.
TEST(NrrdReader, TruncatedPayloadIsRejected)
{
    expectRejected("short.nrrd", smallHeader + "encoding: raw\n\n" + int16Ramp(20), "truncated");
}

TEST(NrrdReader, TruncatedGzipPayloadIsRejected)
{
    const std::string packed = gzipped(int16Ramp(24));
    expectRejected("cut.nrrd", smallHeader + "encoding: gzip\n\n" + packed.substr(0, packed.size() - 12), "truncated");
}

TEST(NrrdReader, HeaderSizeMismatchIsRejected)
{
    expectRejected("long.nrrd", smallHeader + "encoding: raw\n\n" + int16Ramp(30), "size mismatch");
    expectRejected("longgz.nrrd", smallHeader + "encoding: gzip\n\n" + gzipped(int16Ramp(30)), "size mismatch");
}

TEST(NrrdReader, ZeroNegativeAndOverflowingSizesAreRejected)
{
    const std::string rest = "spacings: 1 1 1\nendian: little\nencoding: raw\n\n";
    expectRejected("zero.nrrd", "NRRD0004\ntype: short\ndimension: 3\nsizes: 2 0 4\n" + rest, "dimensions must be positive");
    expectRejected("negative.nrrd", "NRRD0004\ntype: short\ndimension: 3\nsizes: 2 -3 4\n" + rest, "dimensions must be positive");
    expectRejected("huge.nrrd", "NRRD0004\ntype: short\ndimension: 3\nsizes: 100000 100000 100000\n" + rest, "exceeds the limit");
    expectRejected("toolong.nrrd", "NRRD0004\ntype: short\ndimension: 3\nsizes: 99999999999 1 1\n" + rest, "too large");
}

TEST(NrrdReader, DoubleBecomesFloatAsNiftiFloat64DoesOrIsRefusedBeyondItsRange)
{
    // Big-endian doubles, with NaN and a value float32 rounds: read as float(v), as NIfTI float64.
    const std::string dir = tempDirectory();
    const std::vector<double> values = {0.1, -2.5, 1e30, std::nan(""), 3.4e38, 1.0 / 3.0, -1e-30, 42.0};
    auto bytesOf = [](const std::vector<double>& v) {
        std::string bytes;
        for (double x : v) {
            char b[8];
            std::memcpy(b, &x, 8);
            std::reverse(b, b + 8);  // big-endian on this little-endian machine
            bytes.append(b, 8);
        }
        return bytes;
    };
    const std::string header = "NRRD0004\ntype: double\ndimension: 3\nsizes: 2 2 2\nendian: big\nencoding: raw\n\n";
    writeFile(dir + "/ok.nrrd", header + bytesOf(values));
    osg::ref_ptr<Volume> v = readVolumeFile(dir + "/ok.nrrd");
    ASSERT_TRUE(v);
    EXPECT_EQ(v->type(), VoxelType::Float32);
    for (std::size_t i = 0; i < values.size(); ++i) {
        const double expected = double(float(values[i]));
        if (std::isnan(values[i])) EXPECT_TRUE(std::isnan(v->value(i)));
        else EXPECT_EQ(v->value(i), expected) << i;
    }
    std::vector<double> tooBig = values;
    tooBig[6] = -1e39;
    writeFile(dir + "/big.nrrd", header + bytesOf(tooBig));
    const std::string why = expectReadError(dir + "/big.nrrd");
    EXPECT_NE(why.find(dir + "/big.nrrd"), std::string::npos) << why;
    EXPECT_NE(why.find("at voxel 6 is beyond float32's range"), std::string::npos) << why;
}

TEST(NrrdReader, UnknownTypeIsRejected)
{
    expectRejected("weird.nrrd", "NRRD0004\ntype: quaternion\ndimension: 3\nsizes: 1 1 1\nencoding: raw\n\nx", "unsupported type 'quaternion'");
}

TEST(NrrdReader, UnknownEncodingIsRejected)
{
    expectRejected("bz.nrrd", smallHeader + "encoding: bzip2\n\nBZh9", "unsupported encoding 'bzip2'");
    expectRejected("text.nrrd", smallHeader + "encoding: text\n\n1 2 3", "unsupported encoding 'text'");
}

TEST(NrrdReader, CorruptGzipStreamIsRejected)
{
    std::string packed = gzipped(int16Ramp(24));
    for (std::size_t i = 12; i < packed.size() - 8; ++i) packed[i] = char(0xff);
    expectRejected("corrupt.nrrd", smallHeader + "encoding: gzip\n\n" + packed, "corrupt compressed data");
}

TEST(NrrdReader, MissingDetachedDataFileIsRejected)
{
    const std::string dir = tempDirectory();
    writeFile(dir + "/lost.nhdr", smallHeader + "encoding: raw\ndata file: nowhere.raw\n");
    std::string why = expectReadError(dir + "/lost.nhdr");
    EXPECT_NE(why.find(dir + "/lost.nhdr"), std::string::npos) << why;
    EXPECT_NE(why.find("cannot open data file " + dir + "/nowhere.raw: does not exist"), std::string::npos) << why;
    writeFile(dir + "/slices.nhdr", smallHeader + "encoding: raw\ndata file: slice.%d 1 4 1\n");
    why = expectReadError(dir + "/slices.nhdr");
    EXPECT_NE(why.find(dir + "/slice.1: does not exist"), std::string::npos) << why;
}

TEST(NrrdReader, UnreadablePathsAreNamed)
{
    const std::string dir = tempDirectory();
    std::string why = expectReadError(dir + "/nope.nrrd");
    EXPECT_NE(why.find(dir + "/nope.nrrd: no such file"), std::string::npos) << why;
    std::filesystem::create_directories(dir + "/folder.nhdr");
    why = expectReadError(dir + "/folder.nhdr");
    EXPECT_NE(why.find("is a directory"), std::string::npos) << why;
    std::filesystem::create_directories(dir + "/sub");
    writeFile(dir + "/dirdata.nhdr", smallHeader + "encoding: raw\ndata file: sub\n");
    why = expectReadError(dir + "/dirdata.nhdr");
    EXPECT_NE(why.find("data file " + dir + "/sub is a directory"), std::string::npos) << why;
    expectRejected("notnrrd.nrrd", "P5\n2 2\n255\nabcd", "not a NRRD file");
}

TEST(NrrdReader, NonFiniteOrNonPositiveSpacingIsRejected)
{
    const std::string body = "NRRD0004\ntype: uchar\ndimension: 3\nsizes: 1 1 1\nencoding: raw\n";
    expectRejected("nan.nrrd", body + "spacings: 1 nan 1\n\nx", "'nan' is not a positive finite spacing");
    expectRejected("inf.nrrd", body + "spacings: 1 1 inf\n\nx", "'inf' is not a positive finite spacing");
    expectRejected("zero.nrrd", body + "spacings: 0 1 1\n\nx", "'0' is not a positive finite spacing");
    expectRejected("neg.nrrd", body + "spacings: 1 -2 1\n\nx", "'-2' is not a positive finite spacing");
    expectRejected("flat.nrrd", body + "space directions: (1,0,0) (0,0,0) (0,0,1)\n\nx", "has no positive finite length");
}

TEST(NrrdReader, ReportsProgressAndCanBeCancelled)
{
    const std::string dir = tempDirectory();
    const int n = 64 * 64 * 64 * 4;  // 2 MiB of int16: several progress reports
    writeFile(dir + "/big.nrrd", "NRRD0004\ntype: short\ndimension: 3\nsizes: 128 128 64\nendian: little\nencoding: gzip\n\n" +
                                     gzipped(int16Ramp(n)) );
    std::vector<double> seen;
    const LoadProgress record = [&](double f) {
        seen.push_back(f);
        return true;
    };
    osg::ref_ptr<Volume> v = readVolumeFile(dir + "/big.nrrd", withLoadProgress(nullptr, &record).get());
    ASSERT_GE(seen.size(), 2u);
    EXPECT_EQ(seen.back(), 1.0);
    EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));

    int calls = 0;
    const LoadProgress cancel = [&](double) { return ++calls < 2; };
    try {
        readVolumeFile(dir + "/big.nrrd", withLoadProgress(nullptr, &cancel).get());
        ADD_FAILURE() << "cancelled load succeeded";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find(dir + "/big.nrrd: cancelled"), std::string::npos) << e.what();
    }
    EXPECT_EQ(calls, 2);
}

}  // namespace
}  // namespace volren::test
