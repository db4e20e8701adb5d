#include "TestData.h"

#include <volume_model/TransferFunctionFile.h>

#include <gtest/gtest.h>

#include <fstream>

namespace volren::test {
namespace {

std::string writeFile(const std::string& dir, const std::string& name, const std::string& text)
{
    const std::string path = dir + "/" + name;
    std::ofstream(path) << text;
    return path;
}

TEST(TransferFunctionFile, ReadsOsgTfFormatWithDefaultScale255)
{
    const std::string dir = tempDirectory();
    const std::string path = writeFile(dir, "bone.tf",
                                       "# CT bone\n"
                                       "-1000 0 0 0 0\n"
                                       "\n"
                                       "300 255 128 0 51   soft tissue edge\n"
                                       "1200 255 255 255 255\n");
    osg::ref_ptr<TransferFunction> tf = readTransferFunctionFile(path);
    ASSERT_EQ(tf->points().size(), 3u);
    EXPECT_EQ(tf->points().at(-1000.0), osg::Vec4(0, 0, 0, 0));
    const osg::Vec4 mid = tf->points().at(300.0);
    EXPECT_FLOAT_EQ(mid.r(), 1.0f);
    EXPECT_FLOAT_EQ(mid.g(), 128.0f / 255.0f);
    EXPECT_FLOAT_EQ(mid.a(), 0.2f);
    EXPECT_DOUBLE_EQ(tf->domainMin(), -1000.0);
    EXPECT_DOUBLE_EQ(tf->domainMax(), 1200.0);
}

TEST(TransferFunctionFile, ColourScaleLineChangesTheComponentRange)
{
    const std::string dir = tempDirectory();
    const std::string path = writeFile(dir, "unit.tf", "0 0 0 0 0\ncolour-scale 1\n1 0.5 0.25 1 0.125\n");
    osg::ref_ptr<TransferFunction> tf = readTransferFunctionFile(path);
    EXPECT_EQ(tf->points().at(1.0), osg::Vec4(0.5f, 0.25f, 1.0f, 0.125f));
}

TEST(TransferFunctionFile, WriteThenReadGivesTheSamePoints)
{
    const std::string dir = tempDirectory();
    TransferFunction tf;
    tf.setPoint(-3.25, osg::Vec4(0.1f, 0.2f, 0.3f, 1e-7f));
    tf.setPoint(17.5, osg::Vec4(1.0f, 0.0f, 0.5f, 0.9999999f));
    writeTransferFunctionFile(tf, dir + "/out.tf");
    osg::ref_ptr<TransferFunction> back = readTransferFunctionFile(dir + "/out.tf");
    EXPECT_EQ(back->points(), tf.points());
}

TEST(TransferFunctionFile, BadFilesNameFileAndLine)
{
    const std::string dir = tempDirectory();
    struct Case { std::string text, expect; };
    for (const Case& c : {Case{"0 0 0 0 0\n5 1 2 x 4\n", "bad.tf:2: component 'x' is not a number"},
                          Case{"0 0 0\n", "bad.tf:1: expected 'value r g b a', found only 3 numbers"},
                          Case{"10 300 0 0 0\n", "bad.tf:1: component 300"},
                          Case{"colour-scale -2\n", "bad.tf:1: colour-scale needs a positive number"},
                          Case{"# nothing\n", "bad.tf: no control points"}}) {
        const std::string path = writeFile(dir, "bad.tf", c.text);
        try {
            readTransferFunctionFile(path);
            ADD_FAILURE() << "accepted: " << c.text;
        } catch (const std::runtime_error& e) {
            EXPECT_NE(std::string(e.what()).find(c.expect), std::string::npos) << e.what();
        }
    }
    EXPECT_THROW(readTransferFunctionFile(dir + "/missing.tf"), std::runtime_error);
}

}  // namespace
}  // namespace volren::test
