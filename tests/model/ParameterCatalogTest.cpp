// Declared parameters in the model, without the renderer: the catalog's registration rules (a key
// clash fails, the same parameter read by several implementations merges), parsing against the
// declared type and range with errors that name key, value, range and implementation, and
// RenderSettings storing declared values generically (defaults until set, compared by value).
#include <volume_model/ParameterCatalog.h>
#include <volume_model/RenderSettings.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace volren::test {
namespace {

ParameterDecl gain()
{
    return {.key = "testGain", .defaultValue = 0.5, .lo = 0.0, .hi = 2.0, .openLow = true, .unit = "units",
            .help = "a test gain", .aliases = {"testAmplification"}, .slot = "Shading", .implementations = {"glow"}};
}

/// The process-wide catalog with this file's parameters (model_tests links no renderer).
ParameterCatalog& catalog()
{
    static ParameterCatalog& c = [] () -> ParameterCatalog& {
        ParameterCatalog& cat = ParameterCatalog::instance();
        cat.declare(gain());
        cat.declare({.key = "testSteps", .type = ParameterType::Integer, .defaultValue = 4, .lo = 1, .hi = 64,
                     .unit = "steps", .slot = "Acceleration", .implementations = {"hop"}});
        cat.declare({.key = "testView", .type = ParameterType::Choice, .defaultValue = std::string("b"),
                     .choices = {"a", "b", "c"}, .slot = "Shading", .implementations = {"debugging"}});
        cat.declare({.key = "testOn", .type = ParameterType::Switch, .defaultValue = false, .slot = "Jitter"});
        cat.declare({.key = "testLevel", .defaultValue = std::nan(""), .lo = -1e300, .hi = 1e300,
                     .emptyMeans = "the scene's choice", .slot = "RayTraversal", .implementations = {"surface"}});
        cat.declare({.key = "testCurve", .type = ParameterType::Curve, .defaultValue = WeightCurve{},
                     .slot = "Weighting", .implementations = {"along"}});
        return cat;
    }();
    return c;
}

TEST(ParameterCatalog, AKeyTakenByAnotherParameterFailsAtRegistration)
{
    ParameterCatalog local;
    local.declare(gain());
    ParameterDecl other = gain();
    other.slot = "Illumination";  // another slot's parameter under the same key
    try {
        local.declare(other);
        FAIL() << "a clash must throw";
    } catch (const std::logic_error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("'testGain' of Illumination glow"), std::string::npos) << what;
        EXPECT_NE(what.find("Shading glow"), std::string::npos) << what << ": names the holder";
    }
    ParameterDecl wider = gain();
    wider.hi = 3.0;  // the same slot, another range
    EXPECT_THROW(local.declare(wider), std::logic_error);
    ParameterDecl byAlias = {.key = "testAmplification", .lo = 0.0, .hi = 1.0, .slot = "Gradient"};
    EXPECT_THROW(local.declare(byAlias), std::logic_error) << "an alias is taken too";
    ParameterDecl badDefault = {.key = "other", .defaultValue = 5.0, .lo = 0.0, .hi = 1.0, .slot = "Gradient"};
    EXPECT_THROW(local.declare(badDefault), std::logic_error) << "a default outside its range";
    ParameterDecl badPanel = {.key = "other", .defaultValue = 0.5, .lo = 0.0, .hi = 1.0,
                              .panel = {PanelHint::Slider, 0.0, 2.0}, .slot = "Gradient"};
    EXPECT_THROW(local.declare(badPanel), std::logic_error) << "a slider beyond the valid range";
    EXPECT_EQ(local.all().size(), 1u);
}

TEST(ParameterCatalog, TheSameParameterReadByTwoImplementationsIsOneDeclaration)
{
    ParameterCatalog local;
    local.declare(gain());
    ParameterDecl again = gain();
    again.implementations = {"shine"};
    local.declare(again);
    ASSERT_EQ(local.all().size(), 1u);
    EXPECT_TRUE(local.all()[0].readBy("Shading", "glow"));
    EXPECT_TRUE(local.all()[0].readBy("Shading", "shine"));
    EXPECT_FALSE(local.all()[0].readBy("Shading", "lighting"));
    EXPECT_EQ(local.find("TESTAMPLIFICATION"), &local.all()[0]) << "aliases, in any case";
    // A NaN default ("the scene decides") is the same default again (a registry registered twice).
    const ParameterDecl level = {.key = "testLevel", .defaultValue = std::nan(""), .lo = -1.0, .hi = 1.0,
                                 .emptyMeans = "the scene's choice", .slot = "RayTraversal"};
    local.declare(level);
    EXPECT_NO_THROW(local.declare(level));
    EXPECT_EQ(local.all().size(), 2u);
}

TEST(ParameterCatalog, ParseErrorsNameKeyValueRangeAndImplementation)
{
    const ParameterDecl g = gain();
    ParameterValue v;
    std::string error;
    EXPECT_FALSE(g.parse("0", v, error));
    EXPECT_EQ(error, "testGain must be a number in (0, 2] units, got '0' (read by Shading glow)");
    EXPECT_FALSE(g.parse("nan", v, error));
    EXPECT_FALSE(g.parse("", v, error)) << "empty means nothing here";
    ASSERT_TRUE(g.parse("2", v, error)) << error;
    EXPECT_EQ(v, ParameterValue(2.0));
    EXPECT_EQ(g.format(0.1), "0.1") << "the shortest text that reads back";
    const ParameterDecl any = {.key = "testAny", .lo = std::numeric_limits<double>::lowest(),
                               .hi = std::numeric_limits<double>::max(), .slot = "RayTraversal"};
    EXPECT_EQ(any.range(), "any number");
    EXPECT_FALSE(any.parse("x", v, error));
    EXPECT_EQ(error, "testAny must be a number, got 'x' (read by RayTraversal (every implementation))");
}

TEST(RenderSettings, DeclaredParametersHaveTheirDefaultUntilSetAndReadBackAsSet)
{
    catalog();
    RenderSettings s;
    EXPECT_EQ(s.number("testGain"), 0.5);
    EXPECT_EQ(s.get("testGain"), "0.5");
    EXPECT_EQ(s.parameter<int>("testSteps"), 4);
    EXPECT_EQ(s.get("testView"), "b");
    EXPECT_TRUE(std::isnan(s.number("testLevel")));
    EXPECT_EQ(s.get("testLevel"), "") << "empty: the scene's choice";
    EXPECT_THROW(s.number("testSteps"), std::logic_error) << "an Integer is not read as a number";
    EXPECT_THROW(s.number("undeclared"), std::logic_error);
    std::string error;
    for (auto [key, value] : {std::pair{"testGain", "1.25"}, {"testAmplification", "1.5"}, {"testSteps", "8"},
                              {"testView", "c"}, {"testView", "0"}, {"testOn", "on"}, {"testLevel", "-3.5"},
                              {"testLevel", ""}, {"testCurve", "ramp:0.25"}}) {
        RenderSettings t;
        ASSERT_TRUE(t.set(key, value, error)) << key << "=" << value << ": " << error;
        RenderSettings copy;
        ASSERT_TRUE(copy.set(key, t.get(key), error)) << key << ": " << error;
        EXPECT_EQ(copy, t) << key << "=" << value;
    }
    ASSERT_TRUE(s.set("testView", "0", error));
    EXPECT_EQ(s.get("testView"), "a") << "a choice also reads by its index";
    ASSERT_TRUE(s.set("testAmplification", "1.5", error));
    EXPECT_EQ(s.number("testGain"), 1.5) << "an alias sets the parameter";
    for (auto [key, value] : {std::pair{"testGain", "0"}, {"testGain", "2.5"}, {"testSteps", "0"}, {"testSteps", "2.5"},
                              {"testSteps", "65"}, {"testView", "d"}, {"testOn", "sometimes"}, {"testCurve", "1:2"}}) {
        RenderSettings t;
        EXPECT_FALSE(t.set(key, value, error)) << key << "=" << value;
        EXPECT_NE(error.find(value), std::string::npos) << error;
        EXPECT_EQ(t, RenderSettings{}) << "a failed set changes nothing";
    }
}

TEST(RenderSettings, ADeclaredParameterSetToItsDefaultComparesEqualToUnset)
{
    catalog();
    RenderSettings s;
    std::string error;
    ASSERT_TRUE(s.set("testGain", "0.5", error)) << error;
    EXPECT_EQ(s, RenderSettings{});
    ASSERT_TRUE(s.set("testGain", "0.75", error)) << error;
    EXPECT_NE(s, RenderSettings{});
    EXPECT_NE(RenderSettings{}, s);
}

TEST(RenderSettings, KeysListEveryDeclaredParameterWithItsRangeAndReaders)
{
    catalog();
    bool found = false;
    for (const auto& [key, help] : RenderSettings::keys())
        if (key == "testGain") {
            found = true;
            EXPECT_EQ(help, "a test gain (in (0, 2] units; Shading glow)");
        }
    EXPECT_TRUE(found);
}

}  // namespace
}  // namespace volren::test
