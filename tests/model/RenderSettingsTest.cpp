#include <volume_model/RenderSettings.h>

#include <gtest/gtest.h>

namespace volren::test {
namespace {

TEST(RenderSettings, SetParsesEveryKey)
{
    RenderSettings s;
    std::string error;
    ASSERT_TRUE(s.set("sampleFactor", "0.25", error)) << error;
    ASSERT_TRUE(s.set("sampleDistance", "1.5", error)) << error;
    ASSERT_TRUE(s.set("earlyTermination", "1", error)) << error;
    ASSERT_TRUE(s.set("jitter", "off", error)) << error;
    EXPECT_EQ(s.sampleDistanceFactor, 0.25);
    EXPECT_EQ(s.sampleDistance, 1.5);
    EXPECT_EQ(s.earlyTerminationThreshold, 1.0);
    EXPECT_EQ(s.functions.at("Jitter"), "null");
    EXPECT_NE(s, RenderSettings{});
}

TEST(RenderSettings, StorageSettingsReadBackAsTheyWereSet)
{
    RenderSettings s;
    std::string error;
    ASSERT_TRUE(s.set("lod", "2", error)) << error;
    ASSERT_TRUE(s.set("lodByDistance", "on", error)) << error;
    ASSERT_TRUE(s.set("texturePrecision", "16bit", error)) << error;
    EXPECT_EQ(s.texturePrecision, "16bit");
    EXPECT_EQ(s.lod, 2);
    EXPECT_TRUE(s.lodByDistance);
    for (const char* key : {"lod", "lodByDistance", "texturePrecision"}) {
        RenderSettings copy;
        ASSERT_TRUE(copy.set(key, s.get(key), error)) << key << ": " << error;
        EXPECT_EQ(copy.get(key), s.get(key)) << key;
        EXPECT_NE(copy, RenderSettings{}) << key << " takes part in the comparison";
    }
    for (auto [key, value] : {std::pair{"lod", "-1"}, {"lod", "17"}, {"lod", "1.5"},
                              {"lodByDistance", "sometimes"}, {"texturePrecision", "12bit"}}) {
        RenderSettings t;
        EXPECT_FALSE(t.set(key, value, error)) << key << "=" << value;
        EXPECT_NE(error.find(value), std::string::npos) << error;
        EXPECT_EQ(t, RenderSettings{});
    }
}

TEST(RenderSettings, RejectsUnknownKeysAndBadValues)
{
    RenderSettings s;
    std::string error;
    EXPECT_FALSE(s.set("sampelFactor", "1", error));
    EXPECT_NE(error.find("unknown setting 'sampelFactor'"), std::string::npos) << error;
    EXPECT_NE(error.find("sampleFactor"), std::string::npos) << "lists the known keys";
    for (auto [key, value] : {std::pair{"sampleFactor", "0"}, {"sampleFactor", "-1"}, {"sampleFactor", "nan"},
                              {"sampleFactor", "1x"}, {"earlyTermination", "1.5"}, {"jitter", "maybe!"},
                              {"sampleDistance", "-3"}}) {
        EXPECT_FALSE(s.set(key, value, error)) << key << "=" << value;
        EXPECT_NE(error.find(value), std::string::npos) << error;
    }
    EXPECT_EQ(s, RenderSettings{}) << "failed sets change nothing";
}

}  // namespace
}  // namespace volren::test
