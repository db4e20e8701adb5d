#include "TestData.h"

#include <volume_model/ParaViewPreset.h>
#include <volume_model/TransferFunctionFile.h>

#include <gtest/gtest.h>

#include <fstream>

namespace volren::test {
namespace {

// The layout ParaView's "Export Presets" writes: a list of preset objects.
const char* const presets = R"([
    {
        "ColorSpace" : "Diverging",
        "Creator" : "Moreland",
        "Name" : "Cool to Warm",
        "NanColor" : [1, 1, 0],
        "RGBPoints" : [0, 0.23, 0.299, 0.754,  0.5, 0.865, 0.865, 0.865,  1, 0.706, 0.016, 0.15]
    },
    {
        "ColorSpace" : "RGB",
        "Name" : "bone window",
        "Points" : [-1000, 0, 0.5, 0,  200, 0.25, 0.5, 0,  1500, 1, 0.5, 0],
        "RGBPoints" : [-1000, 0, 0, 0,  1500, 1, 0.5, 0]
    },
    { "Name" : "labels", "IndexedColors" : [1, 0, 0, 0, 1, 0], "Annotations" : ["1", "a", "2", "b"] }
])";

std::string presetFile(const std::string& text = presets)
{
    const std::string path = tempDirectory() + "/presets.json";
    std::ofstream(path) << text;
    return path;
}

TEST(ParaViewPreset, FirstPresetGetsItsColoursAndParaViewsStartingOpacityRamp)
{
    osg::ref_ptr<TransferFunction> tf = readParaViewPreset(presetFile());
    EXPECT_EQ(tf->getName(), "Cool to Warm");
    ASSERT_EQ(tf->points().size(), 3u);
    const osg::Vec4 mid = tf->points().at(0.5);
    EXPECT_FLOAT_EQ(mid.r(), 0.865f);
    EXPECT_FLOAT_EQ(mid.a(), 0.5f) << "no \"Points\": opacity ramps 0 -> 1 over the colour range";
    EXPECT_FLOAT_EQ(tf->points().at(0.0).a(), 0.0f);
    EXPECT_FLOAT_EQ(tf->points().at(1.0).b(), 0.15f);
    EXPECT_NEAR(tf->evaluate(0.25).g(), 0.5 * (0.299 + 0.865), 1e-6) << "linear in RGB between points";
}

TEST(ParaViewPreset, OpacityAndColourPointsAtDifferentValuesGiveTheSameFunctions)
{
    osg::ref_ptr<TransferFunction> tf = readTransferFunctionFile(presetFile() + "#bone window");
    EXPECT_EQ(tf->getName(), "bone window");
    ASSERT_EQ(tf->points().size(), 3u) << "union of colour positions {-1000, 1500} and opacity positions {.., 200, ..}";
    const osg::Vec4 at200 = tf->points().at(200.0);
    EXPECT_FLOAT_EQ(at200.a(), 0.25f);
    EXPECT_NEAR(at200.r(), 1200.0 / 2500.0, 1e-6) << "colour at 200 is the colour line's value there";
    EXPECT_NEAR(at200.g(), 0.5 * 1200.0 / 2500.0, 1e-6);
    EXPECT_NEAR(tf->evaluate(850.0).a(), 0.25 + 0.75 * 650.0 / 1300.0, 1e-6);
}

TEST(ParaViewPreset, RemapMovesAPresetOntoTheDataRange)
{
    osg::ref_ptr<TransferFunction> tf = readParaViewPreset(presetFile(), "Cool to Warm");
    tf->remap(-1024.0, 3071.0);
    EXPECT_EQ(tf->domainMin(), -1024.0);
    EXPECT_EQ(tf->domainMax(), 3071.0);
    EXPECT_FLOAT_EQ(tf->points().at(1023.5).r(), 0.865f) << "the middle point lands in the middle of the range";
    EXPECT_THROW(tf->remap(5.0, 5.0), std::invalid_argument);
}

TEST(ParaViewPreset, BadPresetsNameTheFileAndTheProblem)
{
    struct Case { std::string text, name, expect; };
    for (const Case& c : {Case{"{ not json", "", "not valid JSON"},
                          Case{presets, "Viridis", "no preset named 'Viridis' (presets: 'Cool to Warm', 'bone window', 'labels')"},
                          Case{presets, "labels", "categorical presets"},
                          Case{R"({"Name":"x","RGBPoints":[0,1,1]})", "", "not a multiple of 4"},
                          Case{R"({"Name":"x","RGBPoints":[0,1,1,"a"]})", "", "not a finite number"},
                          Case{R"({"Name":"x","RGBPoints":[0,1,1,2]})", "", "outside [0,1]"},
                          Case{R"({"Name":"x","RGBPoints":[0,1,1,1],"Points":[0,0,0.3,0]})", "", "midpoint"},
                          Case{"[1, 2]", "", "no preset objects"}}) {
        const std::string path = presetFile(c.text);
        try {
            readParaViewPreset(path, c.name);
            ADD_FAILURE() << "accepted " << c.text;
        } catch (const std::runtime_error& e) {
            const std::string what = e.what();
            EXPECT_EQ(what.rfind(path, 0), 0u) << what;
            EXPECT_NE(what.find(c.expect), std::string::npos) << what;
        }
    }
}

}  // namespace
}  // namespace volren::test
