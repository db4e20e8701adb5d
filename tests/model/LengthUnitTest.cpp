// Length units as files name them, and scale-bar labels with SI prefixes.
#include <volume_model/LengthUnit.h>

#include <gtest/gtest.h>

namespace volren::test {
namespace {

const std::string micro = "\xC2\xB5m";

TEST(LengthUnit, FileNamesOfUnitsBecomeTheirSymbols)
{
    for (const char* name : {"micron", "Microns", "um", "\xC2\xB5m", "\xCE\xBCm", "micrometer", "micrometre", " micron "})
        EXPECT_EQ(lengthUnitSymbol(name), micro) << name;
    EXPECT_EQ(lengthUnitSymbol("millimeter"), "mm");
    EXPECT_EQ(lengthUnitSymbol("MM"), "mm");
    EXPECT_EQ(lengthUnitSymbol("nanometre"), "nm");
    EXPECT_EQ(lengthUnitSymbol("centimeter"), "cm");
    EXPECT_EQ(lengthUnitSymbol("meter"), "m");
    EXPECT_EQ(lengthUnitSymbol("pixel"), "");
    EXPECT_EQ(lengthUnitSymbol(""), "");
    EXPECT_EQ(lengthUnitSymbol("parsec"), "parsec") << "unknown names are kept";
}

TEST(LengthUnit, AVolumesUnitIsItsSpacingUnitUserValue)
{
    osg::ref_ptr<Volume> v = new Volume;
    EXPECT_EQ(lengthUnitOf(*v), "");
    v->setUserValue(spacingUnitKey, std::string("micrometer"));
    EXPECT_EQ(lengthUnitOf(*v), micro);
}

TEST(LengthUnit, LabelsMoveToThePrefixThatKeepsTheNumberBetweenOneAndAThousand)
{
    EXPECT_EQ(lengthLabel(20, micro), "20 " + micro);
    EXPECT_EQ(lengthLabel(2000, micro), "2 mm");
    EXPECT_EQ(lengthLabel(1500, micro), "1.5 mm");
    EXPECT_EQ(lengthLabel(0.5, "mm"), "500 " + micro);
    EXPECT_EQ(lengthLabel(0.002, micro), "2 nm");
    EXPECT_EQ(lengthLabel(5000, "m"), "5000 m") << "no prefix above metres";
    EXPECT_EQ(lengthLabel(123.456, "mm"), "123 mm");
    EXPECT_EQ(lengthLabel(999.9996, "nm"), "1 \xC2\xB5m") << "rounded before the prefix is chosen";
    EXPECT_EQ(lengthLabel(20, ""), "20");
    EXPECT_EQ(lengthLabel(0.05, ""), "0.05");
    EXPECT_EQ(lengthLabel(10, "parsec"), "10 parsec");
}

}  // namespace
}  // namespace volren::test
