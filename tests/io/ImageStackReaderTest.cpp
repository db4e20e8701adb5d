// Image stack loader (OpenImageIO): numbered folders of PNGs, .imgstack lists, pixel types,
// channels, the spacing option, bad stacks, progress and cancellation.
#include "TestData.h"

#include <volume_model/LoadProgress.h>
#include <volume_model/ReadVolume.h>

#include <osgDB/ReadFile>
#include <osgDB/Registry>
#include <gtest/gtest.h>
#include <OpenImageIO/imageio.h>

#include <filesystem>
#include <fstream>

namespace volren::test {
namespace {

/// Writes a width x height image of `channels` channels of `type` whose sample (x, y, c) is
/// `value + x + 2*y + 3*c` (uint8, uint16 or float).
void writeImage(const std::string& path, int width, int height, int channels, OIIO::TypeDesc type, float value)
{
    std::vector<float> pixels(std::size_t(width * height * channels));
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            for (int c = 0; c < channels; ++c) pixels[std::size_t((y * width + x) * channels + c)] = value + x + 2 * y + 3 * c;
    auto out = OIIO::ImageOutput::create(path);
    ASSERT_TRUE(out) << path << ": " << OIIO::geterror();
    OIIO::ImageSpec spec(width, height, channels, type);
    ASSERT_TRUE(out->open(path, spec)) << out->geterror();
    // Integers are passed in their own type: OIIO would normalise floats (1.0 -> 255).
    if (type == OIIO::TypeDesc::UINT8) {
        std::vector<std::uint8_t> bytes(pixels.begin(), pixels.end());
        ASSERT_TRUE(out->write_image(type, bytes.data())) << out->geterror();
    } else if (type == OIIO::TypeDesc::UINT16) {
        std::vector<std::uint16_t> words(pixels.begin(), pixels.end());
        ASSERT_TRUE(out->write_image(type, words.data())) << out->geterror();
    } else {
        ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, pixels.data())) << out->geterror();
    }
    out->close();
}

double at(const Volume& v, int c, int x, int y, int z)
{
    const osg::Vec3i& d = v.dims();
    return v.storedValue(std::size_t(c) * v.voxelCount() + std::size_t(x) +
                         std::size_t(d.x()) * (std::size_t(y) + std::size_t(d.y()) * std::size_t(z)));
}

/// The volren image stack reader (found by its extension).
osgDB::ReaderWriter* stackPlugin()
{
    registerPluginPath();
    return osgDB::Registry::instance()->getReaderWriterForExtension("imgstack");
}

osg::ref_ptr<Volume> readFolder(const std::string& dir, const osgDB::Options* options = nullptr)
{
    osgDB::ReaderWriter::ReadResult r = stackPlugin()->readObject(dir, options);
    EXPECT_TRUE(r.success()) << r.message();
    return dynamic_cast<Volume*>(r.getObject());
}

std::string folderError(const std::string& dir)
{
    osgDB::ReaderWriter::ReadResult r = stackPlugin()->readObject(dir, nullptr);
    EXPECT_FALSE(r.success()) << dir;
    return r.message();
}


void expectMentions(const std::string& message, const std::string& file, const std::string& reason)
{
    EXPECT_NE(message.find(file), std::string::npos) << message;
    EXPECT_NE(message.find(reason), std::string::npos) << message;
}

TEST(ImageStackReader, PluginIsFoundByExtension)
{
    ASSERT_NE(stackPlugin(), nullptr);
    EXPECT_STREQ(stackPlugin()->className(), "volren image stack reader");
}

TEST(ImageStackReader, NumberedPngFolderStacksInNumericOrder)
{
    const std::string dir = tempDirectory();
    for (int n : {10, 2, 1, 9}) writeImage(dir + "/img" + std::to_string(n) + ".png", 6, 5, 1, OIIO::TypeDesc::UINT8, float(n * 10));
    std::ofstream(dir + "/readme.txt") << "ignored";
    osg::ref_ptr<Volume> v = readFolder(dir);
    ASSERT_TRUE(v.valid());
    EXPECT_EQ(v->dims(), osg::Vec3i(6, 5, 4));
    EXPECT_EQ(v->type(), VoxelType::UInt8);
    EXPECT_EQ(v->channels(), 1);
    const int order[] = {1, 2, 9, 10};
    for (int z = 0; z < 4; ++z)
        for (int y = 0; y < 5; ++y)
            for (int x = 0; x < 6; ++x) ASSERT_EQ(at(*v, 0, x, y, z), order[z] * 10 + x + 2 * y) << x << y << z;
}

TEST(ImageStackReader, ListFileWithRelativePathsAndSpacingOption)
{
    const std::string dir = tempDirectory();
    std::filesystem::create_directories(dir + "/slices");
    for (int n = 0; n < 3; ++n) writeImage(dir + "/slices/a" + std::to_string(n) + ".png", 7, 4, 1, OIIO::TypeDesc::UINT16, 1000.0f * float(n));
    std::ofstream(dir + "/stack.imgstack") << "# three slices, listed out of name order\nslices/a2.png\n\nslices/a0.png\n  slices/a1.png  \n";
    osg::ref_ptr<osgDB::Options> options = new osgDB::Options("spacing=0.5,0.25,2");
    osg::ref_ptr<Volume> v = readVolumeFile(dir + "/stack.imgstack", options.get());
    EXPECT_EQ(v->dims(), osg::Vec3i(7, 4, 3));
    EXPECT_EQ(v->type(), VoxelType::UInt16);
    EXPECT_EQ(v->spacing(), osg::Vec3d(0.5, 0.25, 2));
    EXPECT_EQ(v->sourceFile, dir + "/stack.imgstack");
    const int order[] = {2, 0, 1};
    for (int z = 0; z < 3; ++z) EXPECT_EQ(at(*v, 0, 3, 2, z), 1000.0 * order[z] + 3 + 4) << z;
    v = readVolumeFile(dir + "/stack.imgstack");
    EXPECT_EQ(v->spacing(), osg::Vec3d(1, 1, 1));
    osg::ref_ptr<osgDB::Options> bad = new osgDB::Options("spacing=1,0,2");
    expectMentions(expectReadError(dir + "/stack.imgstack", bad.get()), dir + "/stack.imgstack", "spacing=x,y,z");
}

TEST(ImageStackReader, RgbImagesGiveChannelsAndFloatImagesStayFloat)
{
    const std::string dir = tempDirectory();
    std::filesystem::create_directories(dir + "/rgb");
    std::filesystem::create_directories(dir + "/float");
    std::filesystem::create_directories(dir + "/jpeg");
    for (int n = 0; n < 2; ++n) {
        writeImage(dir + "/rgb/c" + std::to_string(n) + ".png", 5, 3, 3, OIIO::TypeDesc::UINT8, float(n));
        writeImage(dir + "/float/f" + std::to_string(n) + ".tif", 5, 3, 1, OIIO::TypeDesc::FLOAT, 0.25f + float(n));
        writeImage(dir + "/jpeg/j" + std::to_string(n) + ".jpg", 16, 8, 1, OIIO::TypeDesc::UINT8, 100.0f);
    }
    osg::ref_ptr<Volume> rgb = readFolder(dir + "/rgb");
    ASSERT_TRUE(rgb.valid());
    EXPECT_EQ(rgb->channels(), 3);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(at(*rgb, c, 4, 2, 1), 1 + 4 + 4 + 3 * c) << c;
    osg::ref_ptr<Volume> f = readFolder(dir + "/float");
    ASSERT_TRUE(f.valid());
    EXPECT_EQ(f->type(), VoxelType::Float32);
    EXPECT_EQ(at(*f, 0, 2, 1, 1), 1.25 + 2 + 2);
    osg::ref_ptr<Volume> jpeg = readFolder(dir + "/jpeg");
    ASSERT_TRUE(jpeg.valid());
    EXPECT_EQ(jpeg->dims(), osg::Vec3i(16, 8, 2));
    EXPECT_NEAR(at(*jpeg, 0, 0, 0, 0), 100.0, 3.0);  // lossy
}

TEST(ImageStackReader, BadStacksAreRejectedWithFileAndReason)
{
    const std::string dir = tempDirectory();
    // Empty folder, and a folder with no images.
    std::filesystem::create_directories(dir + "/empty");
    expectMentions(folderError(dir + "/empty"), dir + "/empty", "empty directory");
    // Images of different sizes, channel counts or types.
    std::filesystem::create_directories(dir + "/sizes");
    writeImage(dir + "/sizes/s1.png", 6, 5, 1, OIIO::TypeDesc::UINT8, 0);
    writeImage(dir + "/sizes/s2.png", 7, 5, 1, OIIO::TypeDesc::UINT8, 0);
    expectMentions(folderError(dir + "/sizes"), dir + "/sizes/s2.png", "image is 7x5");
    std::filesystem::create_directories(dir + "/types");
    writeImage(dir + "/types/t1.png", 6, 5, 1, OIIO::TypeDesc::UINT8, 0);
    writeImage(dir + "/types/t2.png", 6, 5, 1, OIIO::TypeDesc::UINT16, 0);
    expectMentions(folderError(dir + "/types"), dir + "/types/t2.png", "uint16");
    // A truncated PNG.
    std::filesystem::create_directories(dir + "/cut");
    writeImage(dir + "/cut/c1.png", 64, 64, 1, OIIO::TypeDesc::UINT16, 0);
    writeImage(dir + "/cut/c2.png", 64, 64, 1, OIIO::TypeDesc::UINT16, 0);
    std::filesystem::resize_file(dir + "/cut/c2.png", std::filesystem::file_size(dir + "/cut/c2.png") / 2);
    expectMentions(folderError(dir + "/cut"), dir + "/cut/c2.png", "");
    // Not an image at all.
    std::filesystem::create_directories(dir + "/garbage");
    std::ofstream(dir + "/garbage/g1.png") << "not a png";
    expectMentions(folderError(dir + "/garbage"), dir + "/garbage/g1.png", "cannot read image");
    // Lists: a missing image, no images, and a missing list.
    std::ofstream(dir + "/missing.imgstack") << "sizes/s1.png\nnot-there.png\n";
    expectMentions(expectReadError(dir + "/missing.imgstack"), dir + "/not-there.png", "cannot read image");
    std::ofstream(dir + "/blank.imgstack") << "# nothing\n\n";
    expectMentions(expectReadError(dir + "/blank.imgstack"), dir + "/blank.imgstack", "zero images");
    expectMentions(expectReadError(dir + "/nope.imgstack"), dir + "/nope.imgstack", "no such file");
}

TEST(ImageStackReader, ReportsProgressPerImageAndHonoursCancellation)
{
    const std::string dir = tempDirectory();
    for (int n = 0; n < 5; ++n) writeImage(dir + "/p" + std::to_string(n) + ".png", 4, 4, 1, OIIO::TypeDesc::UINT8, float(n));
    std::vector<double> seen;
    LoadProgress record = [&](double f) {
        seen.push_back(f);
        return true;
    };
    osg::ref_ptr<osgDB::Options> options = withLoadProgress(nullptr, &record);
    ASSERT_TRUE(readFolder(dir, options.get()).valid());
    ASSERT_EQ(seen.size(), 5u);
    EXPECT_DOUBLE_EQ(seen.back(), 1.0);
    int calls = 0;
    LoadProgress cancel = [&](double) { return ++calls < 3; };
    options = withLoadProgress(nullptr, &cancel);
    osgDB::ReaderWriter::ReadResult r = stackPlugin()->readObject(dir, options.get());
    EXPECT_FALSE(r.success());
    expectMentions(r.message(), dir, "cancelled");
    EXPECT_EQ(calls, 3);
}

}  // namespace
}  // namespace volren::test
