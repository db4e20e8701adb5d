// Several inputs on one command line (`--place`, `convert a b scene.osgt`), the data search
// path (OSG_FILE_PATH), the default framing and turntables, through the real `volren` binary.
#include "CliHarness.h"
#include "TestData.h"

#include <gtest/gtest.h>
#include <osgDB/FileNameUtils>
#include <osgDB/FileUtils>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

namespace volren::test {
namespace {

namespace fs = std::filesystem;

/// A 32^3 uint8 NRRD: a ball of 255 (radius 12 voxels) at `centre` (voxels), 0 around it.
void writeBall(const std::string& path, const osg::Vec3d& centre = {15.5, 15.5, 15.5}, double radius = 12.0)
{
    std::ofstream out(path, std::ios::binary);
    out << "NRRD0004\ntype: uint8\ndimension: 3\nsizes: 32 32 32\nspacings: 1 1 1\nencoding: raw\n\n";
    for (int z = 0; z < 32; ++z)
        for (int y = 0; y < 32; ++y)
            for (int x = 0; x < 32; ++x)
                out.put(char((osg::Vec3d(x, y, z) - centre).length() <= radius ? 255 : 0));
}

/// A flat rectangle w x h in the world's xy plane at z = 0, facing +z, as a Wavefront OBJ. OBJ
/// is y-up; OSG's reader turns it z-up ((x, y, z) -> (x, -z, y)), so it is written in the xz plane.
void writeRectangle(const std::string& path, double w, double h)
{
    std::ofstream out(path);
    out << "v " << -w / 2 << " 0 " << h / 2 << "\nv " << w / 2 << " 0 " << h / 2 << "\nv " << w / 2 << " 0 " << -h / 2
        << "\nv " << -w / 2 << " 0 " << -h / 2 << "\nvn 0 1 0\nf 1//1 2//1 3//1 4//1\n";
}

/// Bounding box of the pixels covered (alpha > 0.5): x0, y0, x1, y1 (inclusive; image rows top first).
std::array<int, 4> coveredBox(const Image& img)
{
    std::array<int, 4> box{img.width, img.height, -1, -1};
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x)
            if (img.at(x, y, 3) > 0.5f) {
                box[0] = std::min(box[0], x);
                box[1] = std::min(box[1], y);
                box[2] = std::max(box[2], x);
                box[3] = std::max(box[3], y);
            }
    return box;
}

// Top view, orthographic, 100 world units over 200 pixels: 2 pixels per unit.
const std::string topView = " --size 200x200 --eye 0,0,100 --center 0,0,0 --up 0,1,0 --ortho 100 --set jitter=null";

TEST(SceneInputs, AVolumeAndAModelRenderTogetherAsEachAlone)
{
    const std::string dir = tempDirectory();
    writeBall(dir + "/ball.nrrd");
    writeRectangle(dir + "/plate.obj", 40, 20);
    const std::string place = " --place 2:0,25,5";  // the plate beside the ball, nearer the eye
    ASSERT_EQ(volren("render ball.nrrd -o a.exr" + topView, dir).exitCode, 0);
    CliRun run = volren("render plate.obj -o b.exr --place 1:0,25,5" + topView, dir);
    ASSERT_EQ(run.exitCode, 0) << run.output;
    run = volren("render ball.nrrd plate.obj -o c.exr" + place + topView, dir);
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_NE(run.output.find("ball.nrrd + plate.obj"), std::string::npos) << run.output;
    const Image a = readImage(dir + "/a.exr"), b = readImage(dir + "/b.exr"), c = readImage(dir + "/c.exr");
    int onlyA = 0, onlyB = 0;
    for (int y = 0; y < c.height; ++y)
        for (int x = 0; x < c.width; ++x) {
            const bool inA = a.at(x, y, 3) > 0.01f, inB = b.at(x, y, 3) > 0.5f;
            for (int ch = 0; ch < 4 && inA != inB; ++ch) {
                const Image& alone = inA ? a : b;
                ASSERT_NEAR(c.at(x, y, ch), alone.at(x, y, ch), 2e-3) << "pixel " << x << "," << y;
            }
            onlyA += inA && !inB;
            onlyB += inB && !inA;
            if (!inA && !inB) {
                ASSERT_LT(c.at(x, y, 3), 1e-3f) << "pixel " << x << "," << y;
            }
        }
    EXPECT_GT(onlyA, 1000);
    EXPECT_GT(onlyB, 1000);
}

TEST(SceneInputs, PlacementMovesScalesAndTurnsAModelExactly)
{
    const std::string dir = tempDirectory();
    writeRectangle(dir + "/plate.obj", 40, 20);
    auto boxOf = [&](const std::string& place) {
        const CliRun run = volren("render plate.obj -o p.exr" + place + topView, dir);
        EXPECT_EQ(run.exitCode, 0) << run.output;
        return coveredBox(readImage(dir + "/p.exr"));
    };
    // 40 x 20 units at 2 px/unit: 80 x 40 pixels around the centre (100, 100).
    const auto still = boxOf("");
    EXPECT_NEAR(still[2] - still[0] + 1, 80, 1);
    EXPECT_NEAR(still[3] - still[1] + 1, 40, 1);
    const auto moved = boxOf(" --place 1:20,-10,0");  // +40 px right, +20 px down (rows top first)
    EXPECT_NEAR(moved[0] - still[0], 40, 1);
    EXPECT_NEAR(moved[1] - still[1], 20, 1);
    const auto scaled = boxOf(" --place 1:0,0,0:2,1,1");
    EXPECT_NEAR(scaled[2] - scaled[0] + 1, 160, 1);
    EXPECT_NEAR(scaled[3] - scaled[1] + 1, 40, 1);
    const auto turned = boxOf(" --place 1:0,0,0:z,90");
    EXPECT_NEAR(turned[2] - turned[0] + 1, 40, 1);
    EXPECT_NEAR(turned[3] - turned[1] + 1, 80, 1);
    // Scale, then turn, then move.
    const auto all = boxOf(" --place 1:10,0,0:0.5:0,0,1,90");
    EXPECT_NEAR(all[2] - all[0] + 1, 20, 1);
    EXPECT_NEAR(all[3] - all[1] + 1, 40, 1);
    EXPECT_NEAR((all[0] + all[2]) / 2.0, 100 + 20, 1);
}

TEST(SceneInputs, BadPlacementsAreUsageErrors)
{
    const std::string dir = tempDirectory();
    writeRectangle(dir + "/plate.obj", 40, 20);
    for (const auto& [place, says] : std::vector<std::pair<std::string, std::string>>{
             {"3:0,0,0", "there is 1 input"},
             {"1:0,0", "tx,ty,tz"},
             {"1:0,0,0:-2", "positive"},
             {"1:0,0,0:w,90", "not a number"},
             {"1:0,0,0:0,0,0,90", "non-zero axis"},
             {"x:0,0,0", "--place input number"}}) {
        const CliRun run = volren("render plate.obj -o p.png --place '" + place + "'", dir);
        EXPECT_EQ(run.exitCode, 2) << place << ": " << run.output;
        EXPECT_NE(run.output.find(says), std::string::npos) << place << ": " << run.output;
    }
}

TEST(SceneInputs, ConvertWritesTheCombinedSceneThatRendersTheSameAnywhere)
{
    const std::string dir = tempDirectory();
    writeBall(dir + "/ball.nrrd");
    writeRectangle(dir + "/plate.obj", 40, 20);
    const std::string place = " --place 2:0,25,5:1:x,10";
    CliRun run = volren("render ball.nrrd plate.obj -o direct.exr" + place + topView, dir);
    ASSERT_EQ(run.exitCode, 0) << run.output;
    fs::create_directories(dir + "/scenes");
    run = volren("convert ball.nrrd plate.obj scenes/both.osgt" + place, dir);
    ASSERT_EQ(run.exitCode, 0) << run.output;
    std::ifstream in(dir + "/scenes/both.osgt");
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("\"../plate.obj\""), std::string::npos) << "the model is referred to by a relative path";
    EXPECT_NE(text.find("SourceFile \"../ball.nrrd\""), std::string::npos) << "the volume too";
    EXPECT_NE(text.find("osg::MatrixTransform"), std::string::npos);
    EXPECT_NE(text.find("osg::ProxyNode"), std::string::npos);

    // The scene and its files moved together elsewhere render the same picture.
    const std::string moved = dir + "/elsewhere";
    fs::create_directories(moved + "/scenes");
    for (const char* f : {"ball.nrrd", "plate.obj", "scenes/both.osgt"}) fs::copy_file(dir + "/" + f, moved + "/" + f);
    run = volren("render scenes/both.osgt -o fromscene.exr" + topView, moved);
    ASSERT_EQ(run.exitCode, 0) << run.output;
    const Image direct = readImage(dir + "/direct.exr"), fromScene = readImage(moved + "/fromscene.exr");
    ASSERT_EQ(direct.pixels.size(), fromScene.pixels.size());
    double worst = 0.0;
    for (std::size_t i = 0; i < direct.pixels.size(); ++i) worst = std::max(worst, double(std::abs(direct.pixels[i] - fromScene.pixels[i])));
    EXPECT_LT(worst, 1e-6);
    EXPECT_GT(coveredPixels(fromScene), 1000.0f);

    run = volren("convert ball.nrrd plate.obj out.nrrd", dir);
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_NE(run.output.find("need a scene output"), std::string::npos) << run.output;
}

TEST(SceneInputs, RelativeDataNamesAreFoundAlongOsgFilePath)
{
    const std::string data = tempDirectory() + "/data", scenes = tempDirectory() + "/scenes";
    fs::create_directories(data + "/phantoms");
    fs::create_directories(scenes);
    writeBall(data + "/phantoms/ball.nrrd");
    {
        const CliRun run = volren("convert phantoms/ball.nrrd '" + scenes + "/ball.osgt'", data);
        ASSERT_EQ(run.exitCode, 0) << run.output;
    }
    // The scene names "../<data>/phantoms/ball.nrrd"; make it a bare data-path name.
    std::ifstream in(scenes + "/ball.osgt");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::size_t at = text.find("SourceFile \"");
    ASSERT_NE(at, std::string::npos);
    const std::size_t end = text.find('"', at + 12);
    text.replace(at + 12, end - at - 12, "phantoms/ball.nrrd");
    std::ofstream(scenes + "/ball.osgt") << text;

    CliRun run = volren("render ball.osgt -o x.png --size 32x32", scenes);
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_NE(run.output.find("'phantoms/ball.nrrd' not found"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("'" + scenes + "'"), std::string::npos) << "names the scene's folder: " << run.output;
    EXPECT_NE(run.output.find("share/volren/data'"), std::string::npos) << "names volren's data folder: " << run.output;
    EXPECT_NE(run.output.find("OSG_FILE_PATH"), std::string::npos) << run.output;

    run = volren("render ball.osgt -o x.png --size 32x32", scenes, "OSG_FILE_PATH='/nonexistent:" + data + "' ");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_GT(coveredPixels(readImage(scenes + "/x.png")), 100.0f);
    // A command-line input is looked up the same way.
    run = volren("render phantoms/ball.nrrd -o y.png --size 32x32", scenes, "OSG_FILE_PATH='" + data + "' ");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    run = volren("render phantoms/nothere.nrrd -o y.png --size 32x32", scenes, "OSG_FILE_PATH='" + data + "' ");
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_NE(run.output.find("phantoms/nothere.nrrd: no such file (looked in '" + scenes + "', '" + data + "'"), std::string::npos)
        << run.output;
}

// An installed volren (no checkout beside it) is simulated by a share folder of its own: only
// OSG_FILE_PATH then leads to the shared datasets.
TEST(SceneInputs, EveryExampleSceneRendersFromACopyOfScenesWithOsgFilePath)
{
    VOLREN_REQUIRE_SHARED_DATA();
    const std::string dir = tempDirectory();
    fs::create_directories(dir + "/share/data");
    fs::create_directory_symlink(std::string(VOLREN_BINARY_DIR) + "/share/volren/shaders", dir + "/share/shaders");
    fs::create_symlink(std::string(VOLREN_BINARY_DIR) + "/share/volren/data/ch2.nii.gz", dir + "/share/data/ch2.nii.gz");
    fs::copy(std::string(VOLREN_SOURCE_DIR) + "/scenes", dir + "/scenes");
    const std::string share = "VOLREN_SHARE_DIR='" + dir + "/share' ";
    int scenes = 0;
    for (const auto& entry : fs::directory_iterator(dir + "/scenes")) {
        if (entry.path().extension() != ".osgt") continue;
        ++scenes;
        const std::string name = entry.path().filename().string();
        SCOPED_TRACE(name);
        const std::string render = "render '" + name + "' -o out.png --size 64x64";
        if (name != "default.osgt") {  // its head is in share/volren/data: found without the path
            const CliRun without = volren(render, dir + "/scenes", share);
            EXPECT_EQ(without.exitCode, 1) << without.output;
            EXPECT_NE(without.output.find("not found (looked in"), std::string::npos) << without.output;
        }
        const CliRun run = volren(render, dir + "/scenes", share + "OSG_FILE_PATH='" + sharedData("") + "' ");
        ASSERT_EQ(run.exitCode, 0) << run.output;
        EXPECT_GT(coveredPixels(readImage(dir + "/scenes/out.png")), 300.0f);
    }
    EXPECT_EQ(scenes, 6);
}

TEST(Framing, TheDefaultCameraFitsLongAndFlatVolumesTightlyAtAnyAspect)
{
    const std::string dir = tempDirectory();
    {  // 120 x 10 x 6 voxels, all 200: a long bar, opaque through its TF
        std::ofstream out(dir + "/bar.nrrd", std::ios::binary);
        out << "NRRD0004\ntype: uint8\ndimension: 3\nsizes: 120 10 6\nencoding: raw\n\n" << std::string(120 * 10 * 6, char(200));
        std::ofstream(dir + "/opaque.tf") << "0 255 255 255 255\n255 255 255 255 255\n";
    }
    for (const std::string size : {"240x120", "120x240", "200x200"})
        for (const std::string projection : {"", " --ortho fit"}) {
            SCOPED_TRACE(size + projection);
            const CliRun run = volren("render bar.nrrd -o f.exr --size " + size + projection + " --tf opaque.tf", dir);
            ASSERT_EQ(run.exitCode, 0) << run.output;
            const Image img = readImage(dir + "/f.exr");
            const auto box = coveredBox(img);
            // Nothing touches the border (all corners inside) ...
            EXPECT_GE(box[0], 1);
            EXPECT_GE(box[1], 1);
            EXPECT_LE(box[2], img.width - 2);
            EXPECT_LE(box[3], img.height - 2);
            // ... and along one axis the bar spans the image but for the 3 % margins (and a pixel).
            const double spanX = (box[2] - box[0] + 1.0) / img.width, spanY = (box[3] - box[1] + 1.0) / img.height;
            EXPECT_GT(std::max(spanX, spanY), 0.92) << spanX << " x " << spanY;
        }
}

TEST(Turntable, FramesGoAroundTheSceneAtOneDistanceAndMakeAGif)
{
    const std::string dir = tempDirectory();
    writeBall(dir + "/ball.nrrd");
    writeBall(dir + "/offset.nrrd", {24, 15.5, 15.5}, 6.0);
    // A ball centred in its box turns into itself: every frame the same.
    CliRun run = volren("render ball.nrrd -o t.png --size 64x64 --turntable 4 --set jitter=null", dir);
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_NE(run.output.find("4 frames"), std::string::npos) << run.output;
    for (int k = 1; k <= 4; ++k) EXPECT_TRUE(fs::exists(dir + "/t_000" + std::to_string(k) + ".png")) << k;
    EXPECT_FALSE(fs::exists(dir + "/t_0005.png"));
    EXPECT_FALSE(fs::exists(dir + "/t.png"));
    const Image first = readImage(dir + "/t_0001.png");
    EXPECT_GT(coveredPixels(first), 500.0f);
    for (int k = 2; k <= 4; ++k) {
        const Image other = readImage(dir + "/t_000" + std::to_string(k) + ".png");
        ASSERT_EQ(other.pixels.size(), first.pixels.size());
        double worst = 0.0;
        for (std::size_t i = 0; i < first.pixels.size(); ++i) worst = std::max(worst, double(std::abs(other.pixels[i] - first.pixels[i])));
        EXPECT_LE(worst, 2.0 / 255.0) << "frame " << k;
    }
    // An off-centre ball goes round: it is right of the box centre's column in the first frame
    // (seen from +x+y), left of it half a turn later.
    run = volren("render offset.nrrd -o o.png --size 64x64 --turntable 2 --set jitter=null", dir);
    ASSERT_EQ(run.exitCode, 0) << run.output;
    auto centroidX = [](const Image& img) {
        double sum = 0.0, count = 0.0;
        for (int y = 0; y < img.height; ++y)
            for (int x = 0; x < img.width; ++x)
                if (img.at(x, y, 0) + img.at(x, y, 1) + img.at(x, y, 2) > 0.05f) sum += x, count += 1;
        return count > 0 ? sum / count : -1.0;
    };
    const double x0 = centroidX(readImage(dir + "/o_0001.png")), x1 = centroidX(readImage(dir + "/o_0002.png"));
    EXPECT_LT(x0, 32.0);  // +x points left-ish seen from (0.55, 1, 0.35)
    EXPECT_GT(x1, 32.0);

    run = volren("render offset.nrrd -o spin.gif --size 48x40 --turntable 6 --axis z", dir);
    ASSERT_EQ(run.exitCode, 0) << run.output;
    auto gif = OIIO::ImageInput::open(dir + "/spin.gif");
    ASSERT_TRUE(gif);
    EXPECT_EQ(gif->spec().width, 48);
    EXPECT_EQ(gif->spec().height, 40);
    int frames = 1;
    while (gif->seek_subimage(frames, 0)) ++frames;
    EXPECT_EQ(frames, 6);
}

TEST(TimeSeries, RenderShowsOneTimePointOrEveryOneInTurn)
{
    const std::string dir = tempDirectory();
    {  // 3 time points of 32^3: a small ball at x = 8, 16, 24 voxels
        std::ofstream out(dir + "/moving.mha", std::ios::binary);
        out << "ObjectType = Image\nNDims = 4\nDimSize = 32 32 32 3\nElementType = MET_UCHAR\nElementDataFile = LOCAL\n";
        for (int t = 0; t < 3; ++t)
            for (int z = 0; z < 32; ++z)
                for (int y = 0; y < 32; ++y)
                    for (int x = 0; x < 32; ++x)
                        out.put(char((osg::Vec3d(x, y, z) - osg::Vec3d(8 + 8 * t, 15.5, 15.5)).length() <= 5 ? 255 : 0));
    }
    const std::string view = " --size 64x64" + topView.substr(topView.find(" --eye")) + " --tf-keep-range";
    CliRun run = volren("render moving.mha -o all.exr --time all" + view, dir);
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_NE(run.output.find("(64x64, 3 frames, moving.mha)"), std::string::npos) << run.output;
    EXPECT_FALSE(fs::exists(dir + "/all_0004.exr"));
    // Top view, 100 units over 64 px: the ball moves 8 units = 5.12 px right per time point.
    std::vector<double> centres;
    for (int t = 1; t <= 3; ++t) {
        const auto box = coveredBox(readImage(dir + "/all_000" + std::to_string(t) + ".exr"));
        ASSERT_GE(box[2], 0) << "time point " << t - 1 << " shows nothing";
        centres.push_back((box[0] + box[2]) / 2.0);
    }
    EXPECT_NEAR(centres[1] - centres[0], 5.12, 1.0);
    EXPECT_NEAR(centres[2] - centres[1], 5.12, 1.0);
    // --time 1 alone is the second frame of the sequence.
    run = volren("render moving.mha -o one.exr --time 1" + view, dir);
    ASSERT_EQ(run.exitCode, 0) << run.output;
    const Image one = readImage(dir + "/one.exr"), second = readImage(dir + "/all_0002.exr");
    ASSERT_EQ(one.pixels.size(), second.pixels.size());
    for (std::size_t i = 0; i < one.pixels.size(); ++i) ASSERT_NEAR(one.pixels[i], second.pixels[i], 1e-6) << i;
    run = volren("render moving.mha -o x.png --time 3", dir);
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_NE(run.output.find("time point 3 does not exist (the scene has 3, counted from 0)"), std::string::npos) << run.output;
    // A turntable of 6 frames spreads the 3 time points over the turn.
    run = volren("render moving.mha -o turn.png --size 32x32 --turntable 6 --time all", dir);
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_TRUE(fs::exists(dir + "/turn_0006.png"));
    EXPECT_FALSE(fs::exists(dir + "/turn_0007.png"));
}

}  // namespace
}  // namespace volren::test
