#include "TestData.h"

#include <volume_model/OsgTransferFunction.h>
#include <volume_model/TransferFunctionFile.h>

#include <osgDB/FileUtils>
#include <osgDB/ReadFile>
#include <osgDB/WriteFile>

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <sys/stat.h>

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
    const std::string badDomain = writeFile(dir, "domain.tf", "0 0 0 0 0\n#volren domain 5 5\n");
    EXPECT_THROW(readTransferFunctionFile(badDomain), std::runtime_error);
    const std::string badKey = writeFile(dir, "key.tf", "0 0 0 0 0\n#volren gamma 2\n");
    EXPECT_THROW(readTransferFunctionFile(badKey), std::runtime_error);
}

std::string slurp(const std::string& path)
{
    std::ostringstream text;
    text << std::ifstream(path).rdbuf();
    return text.str();
}

TEST(TransferFunctionFile, DomainAndResolutionSurviveASaveAndLoad)
{
    const std::string dir = tempDirectory();
    TransferFunction tf;
    tf.setPoint(100.0, osg::Vec4(0, 0, 0, 0));
    tf.setPoint(900.0, osg::Vec4(1, 1, 1, 1));
    tf.setDomain(-24.5, 4095.0);
    tf.setResolution(4096);
    writeTransferFunctionFile(tf, dir + "/window.tf");
    osg::ref_ptr<TransferFunction> back = readTransferFunctionFile(dir + "/window.tf");
    EXPECT_EQ(back->points(), tf.points());
    EXPECT_TRUE(back->hasExplicitDomain());
    EXPECT_EQ(back->domainMin(), -24.5);
    EXPECT_EQ(back->domainMax(), 4095.0);
    EXPECT_EQ(back->resolution(), 4096u);
    EXPECT_EQ(back->interpolation(), TransferFunction::Interpolation::Linear);

    // Smooth curves survive too, as a '#volren interpolation' line.
    tf.setInterpolation(TransferFunction::Interpolation::MonotoneCubic);
    writeTransferFunctionFile(tf, dir + "/smooth.tf");
    back = readTransferFunctionFile(dir + "/smooth.tf");
    EXPECT_EQ(back->interpolation(), TransferFunction::Interpolation::MonotoneCubic);
    EXPECT_EQ(back->evaluate(300.0), tf.evaluate(300.0));
    writeFile(dir, "bad.tf", "#volren interpolation cosine\n0 0 0 0 0\n255 255 255 255 255\n");
    try {
        readTransferFunctionFile(dir + "/bad.tf");
        ADD_FAILURE() << "an unknown interpolation must be an error";
    } catch (const std::exception& e) {
        EXPECT_NE(std::string(e.what()).find("bad.tf:1"), std::string::npos) << e.what();
    }
}

TEST(TransferFunctionFile, StockOsgReaderAndVolrenReaderAgree)
{
    // OSG's own osgdb_tf plugin (Debian's openscenegraph) reads both a hand-written 0..255 file
    // and the file volren writes; the points are the same (as floats) as volren's reader gives.
    const std::string dir = tempDirectory();
    const std::string handWritten = writeFile(dir, "ct.tf", "# CT\n-1000 0 0 0 0\n300 255 128 0 51 edge\n1200 255 255 255 255\n");
    TransferFunction written;
    written.setPoint(-0.125, osg::Vec4(0.1f, 0.2f, 0.3f, 0.0f));
    written.setPoint(7.75, osg::Vec4(1.0f, 0.5f, 0.25f, 0.875f));
    written.setDomain(-1.0, 10.0);
    writeTransferFunctionFile(written, dir + "/volren.tf");
    for (const std::string& path : {handWritten, dir + "/volren.tf"}) {
        osg::ref_ptr<osg::TransferFunction1D> stock =
            dynamic_cast<osg::TransferFunction1D*>(osgDB::readRefObjectFile(path).get());
        ASSERT_TRUE(stock) << "osgdb_tf did not read " << path;
        osg::ref_ptr<TransferFunction> ours = readTransferFunctionFile(path);
        osg::ref_ptr<TransferFunction> converted = fromOsgTransferFunction(*stock);
        ASSERT_EQ(converted->points().size(), ours->points().size()) << path;
        for (auto a = converted->points().begin(), b = ours->points().begin(); b != ours->points().end(); ++a, ++b) {
            EXPECT_FLOAT_EQ(float(a->first), float(b->first)) << path;
            for (int c = 0; c < 4; ++c) EXPECT_NEAR(a->second[c], b->second[c], 1e-6f) << path << " value " << b->first;
        }
    }
    // And back: OSG's writer (0..255 scale) gives a file volren reads to the same colours.
    osg::ref_ptr<osg::TransferFunction1D> asOsg = toOsgTransferFunction(written);
    ASSERT_TRUE(osgDB::writeObjectFile(*asOsg, dir + "/fromosg.tf"));
    osg::ref_ptr<TransferFunction> reread = readTransferFunctionFile(dir + "/fromosg.tf");
    ASSERT_EQ(reread->points().size(), 2u);
    EXPECT_NEAR(reread->evaluate(7.75).b(), 0.25f, 1e-6f);
    EXPECT_NEAR(reread->evaluate(7.75).a(), 0.875f, 1e-6f);
}

TEST(TransferFunctionFile, SavingNeverLeavesAHalfWrittenOrReplacedReadOnlyFile)
{
    const std::string dir = tempDirectory();
    TransferFunction tf;
    tf.setPoint(0.0, osg::Vec4(0, 0, 0, 0));
    tf.setPoint(1.0, osg::Vec4(1, 0, 0, 1));
    const std::string path = dir + "/kept.tf";
    writeTransferFunctionFile(tf, path);
    const std::string before = slurp(path);
    ASSERT_EQ(::chmod(path.c_str(), 0444), 0);
    tf.setPoint(0.5, osg::Vec4(0, 1, 0, 1));
    try {
        writeTransferFunctionFile(tf, path);
        ADD_FAILURE() << "replaced a read-only file";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find(path + ": file is read-only"), std::string::npos) << e.what();
    }
    EXPECT_EQ(slurp(path), before);
    EXPECT_THROW(writeTransferFunctionFile(tf, dir + "/no/such/folder/x.tf"), std::runtime_error);
    ::chmod(path.c_str(), 0644);
    writeTransferFunctionFile(tf, path);
    EXPECT_EQ(readTransferFunctionFile(path)->points(), tf.points());
    osgDB::DirectoryContents files = osgDB::getDirectoryContents(dir);
    files.erase(std::remove_if(files.begin(), files.end(), [](const std::string& f) { return f == "." || f == ".."; }),
                files.end());
    EXPECT_EQ(files, osgDB::DirectoryContents{"kept.tf"}) << "no temporary files are left behind";
}

}  // namespace
}  // namespace volren::test
