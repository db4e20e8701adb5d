#include "TestData.h"

#include <volume_model/SlicerVolumeProperty.h>
#include <volume_model/TransferFunctionFile.h>

#include <osg/Notify>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <ostream>

namespace volren::test {
namespace {

// The nine lines Slicer's vtkMRMLVolumePropertyStorageNode writes: interpolation, shade, diffuse,
// ambient, specular, specular power, then "N x y ..." scalar opacity, gradient opacity, and
// "N x r g b ..." colour (N counts the numbers after it).
const char* const ctBone = "1\n"
                           "1\n"
                           "0.9\n"
                           "0.1\n"
                           "0.2\n"
                           "10\n"
                           "8 -1000 0 100 0.25 300 0.5 1200 1\n"
                           "4 0 1 255 1\n"
                           "12 -1000 0 0 0 300 1 0.5 0.25 1200 1 1 1\n";

std::string vpFile(const std::string& text, const std::string& name = "ct-bone.vp")
{
    const std::string path = tempDirectory() + "/" + name;
    writeFile(path, text);
    return path;
}

/// Collects what OSG notifies while it lives.
class CapturedNotices : public osg::NotifyHandler
{
public:
    void notify(osg::NotifySeverity, const char* message) override { text += message; }
    std::string text;
};

TEST(SlicerVolumeProperty, ReadsEveryLineOfSlicersFormat)
{
    const SlicerVolumeProperty vp = readSlicerVolumeProperty(vpFile(ctBone));
    EXPECT_EQ(vp.interpolationType, 1);
    EXPECT_TRUE(vp.shade);
    EXPECT_EQ(vp.diffuse, 0.9);
    EXPECT_EQ(vp.ambient, 0.1);
    EXPECT_EQ(vp.specular, 0.2);
    EXPECT_EQ(vp.specularPower, 10.0);
    ASSERT_EQ(vp.scalarOpacity.size(), 4u);
    EXPECT_EQ(vp.scalarOpacity[1], std::make_pair(100.0, 0.25));
    ASSERT_EQ(vp.gradientOpacity.size(), 2u);
    EXPECT_FALSE(vp.hasGradientOpacity()) << "1 everywhere changes nothing";
    ASSERT_EQ(vp.colour.size(), 3u);
    EXPECT_EQ(vp.colour[1].first, 300.0);
    EXPECT_EQ(vp.colour[1].second, osg::Vec3d(1, 0.5, 0.25));
}

TEST(SlicerVolumeProperty, OpacityAndColourBecomeOneTransferFunctionOverDataValues)
{
    const std::string path = vpFile(ctBone);
    osg::ref_ptr<TransferFunction> tf = readTransferFunctionFile(path);
    EXPECT_EQ(tf->getName(), path);
    EXPECT_FALSE(transferFunctionFitsAnyRange(path)) << "a .vp holds data values";
    ASSERT_EQ(tf->points().size(), 4u) << "union of opacity {-1000, 100, 300, 1200} and colour {-1000, 300, 1200}";
    EXPECT_DOUBLE_EQ(tf->domainMin(), -1000.0);
    EXPECT_DOUBLE_EQ(tf->domainMax(), 1200.0);
    EXPECT_EQ(tf->points().at(-1000.0), osg::Vec4(0, 0, 0, 0));
    EXPECT_EQ(tf->points().at(300.0), osg::Vec4(1.0f, 0.5f, 0.25f, 0.5f));
    EXPECT_EQ(tf->points().at(1200.0), osg::Vec4(1, 1, 1, 1));
    const osg::Vec4 at100 = tf->points().at(100.0);
    EXPECT_FLOAT_EQ(at100.a(), 0.25f);
    EXPECT_NEAR(at100.r(), 1100.0 / 1300.0, 1e-6) << "colour at 100 is the colour line's value there";
    EXPECT_NEAR(at100.g(), 0.5 * 1100.0 / 1300.0, 1e-6);
    EXPECT_NEAR(at100.b(), 0.25 * 1100.0 / 1300.0, 1e-6);
    EXPECT_NEAR(tf->evaluate(200.0).a(), 0.375, 1e-6);
    EXPECT_NEAR(tf->evaluate(750.0).g(), 0.75, 1e-6);
}

TEST(SlicerVolumeProperty, UpperCaseExtensionAndWindowsLineEndingsRead)
{
    std::string crlf;
    for (const char* c = ctBone; *c; ++c) crlf += *c == '\n' ? std::string("\r\n") : std::string(1, *c);
    osg::ref_ptr<TransferFunction> tf = readTransferFunctionFile(vpFile(crlf, "BONE.VP"));
    EXPECT_EQ(tf->points().size(), 4u);
}

TEST(SlicerVolumeProperty, RepeatedPositionIsAStepAsInSlicer)
{
    const SlicerVolumeProperty vp =
        readSlicerVolumeProperty(vpFile("1\n0\n0.7\n0.1\n0.2\n10\n6 0 0 100 0 100 1\n\n8 0 1 0 0 100 0 0 1\n"));
    ASSERT_EQ(vp.scalarOpacity.size(), 3u);
    EXPECT_EQ(vp.scalarOpacity[1].first, 100.0);
    EXPECT_EQ(vp.scalarOpacity[2].first, std::nextafter(100.0, 200.0)) << "moved up by the least amount";
    osg::ref_ptr<TransferFunction> tf = vp.transferFunction();
    EXPECT_EQ(tf->evaluate(99.0).a(), 0.0f);
    EXPECT_EQ(tf->evaluate(100.5).a(), 1.0f);
    EXPECT_NEAR(tf->evaluate(50.0).r(), 0.5, 1e-6);
}

TEST(SlicerVolumeProperty, BlankOptionalLinesKeepTheDefaults)
{
    const SlicerVolumeProperty vp = readSlicerVolumeProperty(vpFile("\n\n\n\n\n\n4 0 0 1 1\n\n4 0.5 1 1 1\n\n\n"));
    EXPECT_EQ(vp.interpolationType, 1);
    EXPECT_FALSE(vp.shade);
    EXPECT_EQ(vp.diffuse, 0.7);
    EXPECT_EQ(vp.specularPower, 10.0);
    EXPECT_TRUE(vp.gradientOpacity.empty());
    EXPECT_EQ(vp.colour.size(), 1u);
    osg::ref_ptr<TransferFunction> tf = vp.transferFunction();
    EXPECT_EQ(tf->evaluate(0.25), osg::Vec4(1, 1, 1, 0.25f)) << "a single colour holds everywhere";
}

TEST(SlicerVolumeProperty, GradientOpacityIsReadButIgnoredWithANotice)
{
    const std::string path = vpFile("1\n1\n0.9\n0.1\n0.2\n10\n4 0 0 1 1\n4 0 0 50 1\n8 0 0 0 0 1 1 1 1\n");
    EXPECT_TRUE(readSlicerVolumeProperty(path).hasGradientOpacity());

    osg::ref_ptr<osg::NotifyHandler> previousHandler = osg::getNotifyHandler();
    const osg::NotifySeverity previousLevel = osg::getNotifyLevel();
    osg::ref_ptr<CapturedNotices> captured = new CapturedNotices;
    osg::setNotifyHandler(captured.get());
    osg::setNotifyLevel(osg::NOTICE);
    osg::ref_ptr<TransferFunction> tf = readTransferFunctionFile(path);
    osg::setNotifyHandler(previousHandler.get());
    osg::setNotifyLevel(previousLevel);

    EXPECT_NE(captured->text.find(path + ": the gradient opacity is ignored"), std::string::npos) << captured->text;
    EXPECT_EQ(tf->evaluate(0.5), osg::Vec4(0.5f, 0.5f, 0.5f, 0.5f)) << "classification by value only";
}

// Every bad input is an error naming "file:line" (or the file) and the reason; one test per case.
struct BadVp
{
    const char* name;
    std::string text;
    const char* where;  // ":line:" expected after the path, or ": " for the whole file
    const char* reason;
};

/// What GoogleTest (and ctest's test list) shows of a case: its name.
void PrintTo(const BadVp& c, std::ostream* out) { *out << c.name; }

class SlicerVolumePropertyRejects : public ::testing::TestWithParam<BadVp>
{
};

TEST_P(SlicerVolumePropertyRejects, NamingFileLineAndReason)
{
    const BadVp& c = GetParam();
    const std::string path = vpFile(c.text);
    try {
        readTransferFunctionFile(path);
        ADD_FAILURE() << "accepted:\n" << c.text;
    } catch (const std::runtime_error& e) {
        const std::string what = e.what();
        EXPECT_EQ(what.rfind(path + c.where, 0), 0u) << what;
        EXPECT_NE(what.find(c.reason), std::string::npos) << what;
    }
}

const std::string head = "1\n1\n0.9\n0.1\n0.2\n10\n";  // lines 1-6, all fine
const std::string opacity = "4 0 0 100 1\n";          // line 7
const std::string gradient = "4 0 1 255 1\n";         // line 8
const std::string colour = "8 0 0 0 0 100 1 1 1\n";   // line 9

INSTANTIATE_TEST_SUITE_P(
    SlicerVolumeProperty, SlicerVolumePropertyRejects,
    ::testing::Values(
        BadVp{"EmptyFile", "", ": ", "empty file"},
        BadVp{"BlankFile", "\n \n\n", ": ", "empty file"},
        BadVp{"Truncated", head + opacity + gradient, ":8:", "ends after line 8; a Slicer volume property has 9 lines (the colour transfer function is missing)"},
        BadVp{"CountLargerThanTheNumbers", head + "6 0 0 100 1\n" + gradient + colour, ":7:", "count says 6 numbers, the line has 4"},
        BadVp{"CountSmallerThanTheNumbers", head + opacity + gradient + "4 0 0 0 0 100 1 1 1\n", ":9:", "count says 4 numbers, the line has 8"},
        BadVp{"CountNotPairs", head + "3 0 0 100\n" + gradient + colour, ":7:", "count 3 is not a multiple of 2"},
        BadVp{"CountNotQuadruples", head + opacity + gradient + "6 0 0 0 100 1 1\n", ":9:", "count 6 is not a multiple of 4"},
        BadVp{"CountNotAWholeNumber", head + "2.5 0 0\n" + gradient + colour, ":7:", "count 2.5 is not a whole number"},
        BadVp{"NoOpacityPoints", head + "0\n" + gradient + colour, ":7:", "the scalar opacity function has no points"},
        BadVp{"MissingColourLine", head + opacity + gradient + "\n", ":9:", "expected the colour transfer function"},
        BadVp{"NotANumberInALightingLine", "linear\n1\n0.9\n0.1\n0.2\n10\n" + opacity + gradient + colour, ":1:", "interpolation type: 'linear' is not a finite number"},
        BadVp{"TwoNumbersOnALightingLine", "1\n1\n0.9 0.8\n0.1\n0.2\n10\n" + opacity + gradient + colour, ":3:", "expected one number (the diffuse reflection), found 2 words"},
        BadVp{"ShadeNotAFlag", "1\n2\n0.9\n0.1\n0.2\n10\n" + opacity + gradient + colour, ":2:", "the shade flag must be 0 or 1"},
        BadVp{"NotANumberInAFunction", head + "4 0 0 100 high\n" + gradient + colour, ":7:", "scalar opacity function: 'high' is not a finite number"},
        BadVp{"NaN", head + opacity + gradient + "8 0 0 0 0 100 nan 1 1\n", ":9:", "colour transfer function: 'nan' is not a finite number"},
        BadVp{"Infinity", head + "4 -inf 0 100 1\n" + gradient + colour, ":7:", "'-inf' is not a finite number"},
        BadVp{"OpacityAboveOne", head + "4 0 0 100 1.5\n" + gradient + colour, ":7:", "1.5 at 100 is outside [0,1]"},
        BadVp{"ColourBelowZero", head + opacity + gradient + "8 0 0 0 0 100 1 -0.5 1\n", ":9:", "-0.5 at 100 is outside [0,1]"},
        BadVp{"ColourIn0To255", head + opacity + gradient + "8 0 0 0 0 100 255 255 255\n", ":9:", "255 at 100 is outside [0,1]"},
        BadVp{"DecreasingPositions", head + "4 100 0 0 1\n" + gradient + colour, ":7:", "positions must not decrease"},
        BadVp{"BadGradientLine", head + opacity + "3 0 1 255\n" + colour, ":8:", "gradient opacity function: count 3 is not a multiple of 2"},
        BadVp{"TextAfterTheNineLines", head + opacity + gradient + colour + "\n1\n", ":11:", "unexpected text after the 9 lines"}),
    [](const ::testing::TestParamInfo<BadVp>& info) { return std::string(info.param.name); });

TEST(SlicerVolumeProperty, MissingFileIsAnErrorNamingIt)
{
    const std::string path = tempDirectory() + "/absent.vp";
    try {
        readTransferFunctionFile(path);
        ADD_FAILURE() << "read a missing file";
    } catch (const std::runtime_error& e) {
        EXPECT_EQ(std::string(e.what()), path + ": cannot open Slicer volume property file");
    }
}

}  // namespace
}  // namespace volren::test
