#include "TestData.h"

#include <volume_model/ImageJLut.h>
#include <volume_model/TransferFunctionFile.h>

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <ostream>
#include <sstream>

namespace volren::test {
namespace {

// A LUT whose entries are known in closed form: red rises, green falls, blue steps by 7.
int red(int i) { return i; }
int green(int i) { return 255 - i; }
int blue(int i) { return (i * 7) % 256; }

/// The 768-byte raw form: 256 reds, 256 greens, 256 blues.
std::string rawPlanes()
{
    std::string bytes;
    for (int (*channel)(int) : {red, green, blue})
        for (int i = 0; i < 256; ++i) bytes += char(channel(i));
    return bytes;
}

/// NIH Image's 32-byte header: "ICOL", version, nColors, start, end (big-endian 16-bit), filler.
std::string nihHeader(int colours)
{
    std::string h = "ICOL";
    for (int v : {1, colours, 0, colours - 1}) h += std::string{char((v >> 8) & 0xff), char(v & 0xff)};
    return h + std::string(20, '\0');
}

/// ImageJ's "Save LUT as text" layout: a heading, then "index<TAB>r<TAB>g<TAB>b".
std::string textLut(bool heading, bool indexColumn, const std::string& separator = "\t", const std::string& eol = "\n",
                    int rows = 256)
{
    std::ostringstream out;
    if (heading) out << (indexColumn ? "Index" + separator : std::string()) << "Red" << separator << "Green" << separator << "Blue" << eol;
    for (int i = 0; i < rows; ++i) {
        if (indexColumn) out << i << separator;
        out << red(i % 256) << separator << green(i % 256) << separator << blue(i % 256) << eol;
    }
    return out.str();
}

std::string lutFile(const std::string& bytes, const std::string& name = "ramp.lut")
{
    const std::string path = tempDirectory() + "/" + name;
    writeFile(path, bytes);
    return path;
}

/// Entry i of the closed-form LUT as the reader should give it: opacity i / 255.
osg::Vec4 expected(int i)
{
    return osg::Vec4(float(red(i) / 255.0), float(green(i) / 255.0), float(blue(i) / 255.0), float(i / 255.0));
}

void expectClosedFormLut(const TransferFunction& tf)
{
    ASSERT_EQ(tf.points().size(), 256u);
    EXPECT_TRUE(tf.hasExplicitDomain());
    EXPECT_EQ(tf.domainMin(), 0.0);
    EXPECT_EQ(tf.domainMax(), 255.0);
    for (int i : {0, 1, 10, 37, 128, 254, 255}) EXPECT_EQ(tf.points().at(double(i)), expected(i)) << "entry " << i;
    EXPECT_NEAR(tf.evaluate(10.5).g(), (245.0 + 244.0) / 2 / 255.0, 1e-6) << "linear between entries";
}

TEST(ImageJLut, Raw768ByteFormReadsOneEntryPerValueWithAnOpacityRamp)
{
    const std::string path = lutFile(rawPlanes());
    EXPECT_TRUE(transferFunctionFitsAnyRange(path)) << "a LUT holds no data values";
    osg::ref_ptr<TransferFunction> tf = readTransferFunctionFile(path);
    EXPECT_EQ(tf->getName(), path);
    expectClosedFormLut(*tf);
}

TEST(ImageJLut, RemapStretchesTheTableOverTheVolumesRange)
{
    osg::ref_ptr<TransferFunction> tf = readImageJLut(lutFile(rawPlanes()));
    tf->remap(-1000.0, 1550.0);
    EXPECT_EQ(tf->domainMin(), -1000.0);
    EXPECT_EQ(tf->domainMax(), 1550.0);
    EXPECT_EQ(tf->points().begin()->first, -1000.0);
    EXPECT_EQ(tf->points().rbegin()->first, 1550.0);
    EXPECT_EQ(tf->points().at(-1000.0 + 10 * 10.0), expected(10)) << "entry 10 of 255 lands 10/255 of the way";
}

TEST(ImageJLut, NihImage800ByteFormWithIcolHeader)
{
    const std::string bytes = nihHeader(256) + rawPlanes();
    ASSERT_EQ(bytes.size(), 800u);
    expectClosedFormLut(*readTransferFunctionFile(lutFile(bytes, "nih.LUT")));
}

TEST(ImageJLut, NihImageLutOfFewerColoursSpreadsThemAsImageJDoes)
{
    // 4 colours: ImageJ puts colour k at entry k * 256 / 4 and holds the last one to entry 255.
    const std::string planes = std::string{char(0), char(100), char(200), char(255)} + std::string(4, char(50)) +
                               std::string{char(255), char(0), char(255), char(0)};
    osg::ref_ptr<TransferFunction> tf = readImageJLut(lutFile(nihHeader(4) + planes));
    ASSERT_EQ(tf->points().size(), 5u);
    EXPECT_EQ(tf->points().at(64.0), osg::Vec4(float(100 / 255.0), float(50 / 255.0), 0.0f, float(64 / 255.0)));
    EXPECT_EQ(tf->points().at(255.0), osg::Vec4(1.0f, float(50 / 255.0), 0.0f, 1.0f));
    EXPECT_NEAR(tf->evaluate(32.0).r(), 50 / 255.0, 1e-6) << "ImageJ's entry 32 is halfway between colours 0 and 1";
    EXPECT_NEAR(tf->evaluate(224.0).r(), 1.0, 1e-6) << "held after the last colour";
}

TEST(ImageJLut, TextWithThreeColumnsAndNoHeading)
{
    expectClosedFormLut(*readTransferFunctionFile(lutFile(textLut(false, false, " "))));
}

TEST(ImageJLut, TextAsImageJSavesIt)
{
    // "Index\tRed\tGreen\tBlue" then 256 rows, here with Windows line endings.
    expectClosedFormLut(*readTransferFunctionFile(lutFile(textLut(true, true, "\t", "\r\n"))));
}

TEST(ImageJLut, CommaSeparatedTextWithHeading)
{
    expectClosedFormLut(*readImageJLut(lutFile(textLut(true, false, ","))));
}

TEST(ImageJLut, IndexColumnIsNotUsedAsImageJIgnoresIt)
{
    std::string text;
    for (int i = 0; i < 256; ++i)
        text += std::to_string(i + 1) + " " + std::to_string(red(i)) + " " + std::to_string(green(i)) + " " +
                std::to_string(blue(i)) + "\n";
    expectClosedFormLut(*readImageJLut(lutFile(text)));
}

TEST(ImageJLut, RealLutFileFromDebian)
{
    // mricron-data ships ImageJ-style 768-byte LUTs; compare with the bytes read independently.
    const std::string path = "/usr/share/mricron/lut/NIH_fire.lut";
    if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " is not installed (Debian package mricron-data)";
    std::ifstream in(path, std::ios::binary);
    const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    ASSERT_EQ(bytes.size(), 768u);
    osg::ref_ptr<TransferFunction> tf = readTransferFunctionFile(path);
    ASSERT_EQ(tf->points().size(), 256u);
    for (int i = 0; i < 256; i += 15) {
        const osg::Vec4 c = tf->points().at(double(i));
        EXPECT_EQ(c.r(), float(std::uint8_t(bytes[i]) / 255.0)) << i;
        EXPECT_EQ(c.g(), float(std::uint8_t(bytes[256 + i]) / 255.0)) << i;
        EXPECT_EQ(c.b(), float(std::uint8_t(bytes[512 + i]) / 255.0)) << i;
    }
}

// Every bad input is an error naming the file (and "file:line" in text) and the reason; one test per case.
struct BadLut
{
    const char* name;
    std::string bytes;
    const char* where;  // ":line:" expected after the path, or ": " for the whole file
    const char* reason;
};

/// What GoogleTest (and ctest's test list) shows of a case: its name.
void PrintTo(const BadLut& c, std::ostream* out) { *out << c.name; }

class ImageJLutRejects : public ::testing::TestWithParam<BadLut>
{
};

TEST_P(ImageJLutRejects, NamingFileAndReason)
{
    const BadLut& c = GetParam();
    const std::string path = lutFile(c.bytes);
    try {
        readTransferFunctionFile(path);
        ADD_FAILURE() << "accepted " << c.name;
    } catch (const std::runtime_error& e) {
        const std::string what = e.what();
        EXPECT_EQ(what.rfind(path + c.where, 0), 0u) << what;
        EXPECT_NE(what.find(c.reason), std::string::npos) << what;
    }
}

/// `text` with row `row` (0-based, after no heading) replaced by `replacement`.
std::string withRow(int row, const std::string& replacement)
{
    std::istringstream in(textLut(false, false, " "));
    std::string line, out;
    for (int i = 0; std::getline(in, line); ++i) out += (i == row ? replacement : line) + "\n";
    return out;
}

INSTANTIATE_TEST_SUITE_P(
    ImageJLut, ImageJLutRejects,
    ::testing::Values(
        BadLut{"EmptyFile", "", ": ", "empty file"},
        BadLut{"Raw767Bytes", rawPlanes().substr(1), ": ", "767 bytes of binary data (an ImageJ LUT is 768 bytes raw"},
        BadLut{"Raw769Bytes", rawPlanes() + '\0', ": ", "769 bytes of binary data"},
        BadLut{"NihTruncated", (nihHeader(256) + rawPlanes()).substr(0, 500), ": ", "NIH Image LUT of 256 colours is 800 bytes, the file has 500 (truncated)"},
        BadLut{"NihTooLong", nihHeader(256) + rawPlanes() + "xx", ": ", "is 800 bytes, the file has 802"},
        BadLut{"NihHeaderTruncated", nihHeader(256).substr(0, 20), ": ", "truncated in its 32-byte header (20 bytes)"},
        BadLut{"NihNoColours", nihHeader(0), ": ", "header says 0 colours; expected 1..256"},
        BadLut{"NihTooManyColours", nihHeader(300) + std::string(900, '\0'), ": ", "header says 300 colours"},
        BadLut{"TextTooFewRows", textLut(true, true, "\t", "\n", 255), ":256:", "expected 256 rows (one per LUT entry), the file has 255"},
        BadLut{"TextTooManyRows", textLut(false, false, " ", "\n", 257), ":257:", "more than 256 rows"},
        BadLut{"TextNotANumber", withRow(9, "10 x 70"), ":10:", "green 'x' is not a finite number"},
        BadLut{"TextNaN", withRow(0, "nan 255 0"), ":1:", "red 'nan' is not a finite number"},
        BadLut{"TextAbove255", withRow(99, "99 156 256"), ":100:", "blue 256 is outside 0..255"},
        BadLut{"TextNegative", withRow(5, "-1 250 35"), ":6:", "red -1 is outside 0..255"},
        BadLut{"TextTwoColumns", withRow(3, "3 252"), ":4:", "expected 'r g b' or 'index r g b', found 2 words"},
        BadLut{"TextColumnsChange", withRow(7, "7 7 248 49"), ":8:", "expected 3 columns like the first row, found 4"},
        BadLut{"TextSecondHeading", "Red Green Blue\n" + withRow(0, "Red Green Blue"), ":2:", "red 'Red' is not a finite number"}),
    [](const ::testing::TestParamInfo<BadLut>& info) { return std::string(info.param.name); });

TEST(ImageJLut, MissingFileIsAnErrorNamingIt)
{
    const std::string path = tempDirectory() + "/absent.lut";
    try {
        readTransferFunctionFile(path);
        ADD_FAILURE() << "read a missing file";
    } catch (const std::runtime_error& e) {
        EXPECT_EQ(std::string(e.what()), path + ": cannot open lookup-table file");
    }
}

}  // namespace
}  // namespace volren::test
