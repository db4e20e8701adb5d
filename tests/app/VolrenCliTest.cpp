// The `volren` program's contract: commands, outputs, statistics and errors with exit codes.
#include "CliHarness.h"
#include "TestData.h"

#include <volume_model/ReadVolume.h>

#include <OpenImageIO/imageio.h>
#include <nlohmann/json.hpp>
#include <gtest/gtest.h>
#include <osgDB/FileUtils>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <cmath>
#include <fstream>
#include <sstream>
#include <sys/wait.h>

namespace volren::test {
namespace {

/// Expects `converted` to hold `original`'s voxels: dims, spacing and bytes.
void expectSameVoxels(const Volume& converted, const Volume& original)
{
    ASSERT_EQ(converted.dims(), original.dims());
    EXPECT_EQ(converted.spacing(), original.spacing());
    ASSERT_EQ(converted.byteSize(), original.byteSize());
    EXPECT_EQ(std::memcmp(converted.data(), original.data(), original.byteSize()), 0);
}

TEST(VolrenCli, NoArgumentsRendersTheDefaultSceneToVolrenPng)
{
    const std::string dir = tempDirectory();
    const CliRun run = volren("", dir);
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_NE(run.output.find("wrote " + dir + "/volren.png"), std::string::npos) << run.output;
    const Image img = readImage(dir + "/volren.png");
    ASSERT_EQ(img.width, 512);
    ASSERT_EQ(img.height, 512);
    // The head fills the middle; the corners are black background.
    EXPECT_GT(img.at(256, 256, 0), 0.2f);
    for (auto [x, y] : {std::pair{0, 0}, {511, 0}, {0, 511}, {511, 511}})
        for (int c = 0; c < 3; ++c) EXPECT_EQ(img.at(x, y, c), 0.0f);
    // scenes/default.osgt (compiled in) is the default scene of the head it names.
    const CliRun bare = volren("render '" + std::string(VOLREN_BINARY_DIR) + "/share/volren/data/ch2.nii.gz' -o bare.png", dir);
    ASSERT_EQ(bare.exitCode, 0) << bare.output;
    EXPECT_EQ(readImage(dir + "/bare.png").pixels, img.pixels);
}

TEST(VolrenCli, ReferenceAndCompareMeasureTheGpuAgainstTheIntegral)
{
    VOLREN_REQUIRE_SHARED_DATA();
    const std::string dir = tempDirectory();
    const std::string volume = sharedData("mri/HeadMRVolume.mhd");
    const std::string view = " --size 64x64 --set lighting=off";
    CliRun run = volren("reference '" + volume + "' -o '" + dir + "/ref.exr'" + view);
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_NE(run.output.find("0 rays not converged"), std::string::npos) << run.output;
    run = volren("render '" + volume + "' -o '" + dir + "/gpu.exr'" + view + " --set jitter=null --set earlyTermination=1 --set samplerate=4");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    const Image ref = readImage(dir + "/ref.exr"), gpu = readImage(dir + "/gpu.exr");
    ASSERT_EQ(ref.pixels.size(), gpu.pixels.size());
    double sumSquares = 0.0;
    for (std::size_t i = 0; i < ref.pixels.size(); ++i) sumSquares += double(ref.pixels[i] - gpu.pixels[i]) * (ref.pixels[i] - gpu.pixels[i]);
    const double rmse = std::sqrt(sumSquares / double(ref.pixels.size()));
    EXPECT_LT(rmse, 1e-3);
    EXPECT_GT(rmse, 0.0) << "two different integrators";

    // compare prints the same RMSE (OpenImageIO's measure), and the difference image.
    run = volren("compare '" + dir + "/gpu.exr' '" + dir + "/ref.exr' --diff '" + dir + "/diff.exr'");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    const std::size_t at = run.output.find("RMSE:");
    ASSERT_NE(at, std::string::npos) << run.output;
    EXPECT_NEAR(std::stod(run.output.substr(at + 5)), rmse, 1e-6) << run.output;
    const Image diff = readImage(dir + "/diff.exr");
    ASSERT_EQ(diff.pixels.size(), ref.pixels.size());
    for (std::size_t i = 0; i < diff.pixels.size(); i += 97) EXPECT_NEAR(diff.pixels[i], std::abs(gpu.pixels[i] - ref.pixels[i]), 1e-6);
    run = volren("compare '" + dir + "/ref.exr' '" + dir + "/ref.exr'");
    EXPECT_NE(run.output.find("RMSE:           0\n"), std::string::npos) << run.output;
    run = volren("render '" + volume + "' -o '" + dir + "/small.png' --size 32x32");
    run = volren("compare '" + dir + "/ref.exr' '" + dir + "/small.png'");
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_NE(run.output.find(dir + "/small.png: 32x32 differs from"), std::string::npos) << run.output;
}

TEST(VolrenCli, ConvertToASceneFileWritesTheVolumesDefaultScene)
{
    VOLREN_REQUIRE_SHARED_DATA();
    const std::string dir = tempDirectory();
    const std::string volume = sharedData("mri/HeadMRVolume.mhd");
    for (const char* ext : {"osgt", "osgb"}) {
        const std::string scene = dir + "/head." + ext;
        CliRun run = volren("convert '" + volume + "' '" + scene + "'");
        ASSERT_EQ(run.exitCode, 0) << run.output;
        EXPECT_NE(run.output.find("(default scene; 48 x 62 x 42 uint8"), std::string::npos) << run.output;
        run = volren("render '" + scene + "' -o '" + dir + "/scene.png' --size 64x64");
        ASSERT_EQ(run.exitCode, 0) << run.output;
        run = volren("render '" + volume + "' -o '" + dir + "/bare.png' --size 64x64");
        ASSERT_EQ(run.exitCode, 0) << run.output;
        const Image fromScene = readImage(dir + "/scene.png");
        ASSERT_EQ(fromScene.width, 64);
        EXPECT_EQ(fromScene.pixels, readImage(dir + "/bare.png").pixels) << ext;
    }
}

TEST(VolrenCli, ParaViewPresetIsFittedToTheDataRangeUnlessKeptAsIs)
{
    VOLREN_REQUIRE_SHARED_DATA();
    const std::string dir = tempDirectory();
    const std::string volume = sharedData("mri/ch2.nii.gz");  // values 0 .. 254
    // Red at 0, blue at 1; opacity 0 at 0, 1 at 1.
    std::ofstream(dir + "/p.json") << R"([{"Name":"red-blue","ColorSpace":"RGB",
        "RGBPoints":[0,1,0,0, 1,0,0,1], "Points":[0,0,0.5,0, 1,1,0.5,0]}])";
    const std::string common = " --size 32x32 --ortho 400 --set jitter=off --set lighting=off --tf '" + dir + "/p.json#red-blue'";
    CliRun run = volren("render '" + volume + "' -o '" + dir + "/kept.png'" + common + " --tf-keep-range");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    // Kept: every tissue value (>= 1) is opaque pure blue, so the first tissue samples decide
    // (values between 0 and 1 on the air's border add a trace of red: 3 % measured).
    Image img = readImage(dir + "/kept.png");
    EXPECT_GT(img.at(16, 16, 2), 0.95f);
    EXPECT_LT(img.at(16, 16, 0), 0.05f);
    run = volren("render '" + volume + "' -o '" + dir + "/fitted.png'" + common);
    ASSERT_EQ(run.exitCode, 0) << run.output;
    // Fitted onto 0 .. 254: tissue is partly red and no longer opaque at its first sample.
    img = readImage(dir + "/fitted.png");
    EXPECT_GT(img.at(16, 16, 0), 0.05f);
    EXPECT_LT(img.at(16, 16, 2), 0.95f);
    run = volren("render '" + volume + "' -o '" + dir + "/x.png'" + " --tf '" + dir + "/p.json#nope'");
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_NE(run.output.find(dir + "/p.json: no preset named 'nope' (presets: 'red-blue')"), std::string::npos) << run.output;
}

TEST(VolrenCli, SlicerVolumePropertyAndImageJLutAreTransferFunctions)
{
    VOLREN_REQUIRE_SHARED_DATA();
    const std::string dir = tempDirectory();
    const std::string volume = sharedData("mri/ch2.nii.gz");  // values 0 .. 254
    const std::string common = " --size 32x32 --ortho 400 --set jitter=off --set lighting=off";
    // Slicer: opacity 0 at 0, 1 from 1 on (data values, used as they are); blue everywhere.
    std::ofstream(dir + "/blue.vp") << "1\n0\n0.7\n0.2\n0.2\n10\n4 0 0 1 1\n4 0 1 255 1\n8 0 0 0 1 1 0 0 1\n";
    CliRun run = volren("render '" + volume + "' -o '" + dir + "/vp.png' --tf '" + dir + "/blue.vp'" + common);
    ASSERT_EQ(run.exitCode, 0) << run.output;
    Image img = readImage(dir + "/vp.png");
    EXPECT_GT(img.at(16, 16, 2), 0.95f);
    EXPECT_LT(img.at(16, 16, 0) + img.at(16, 16, 1), 0.02f);
    // ImageJ's raw 768-byte LUT: a red ramp (opacity rises with the entry), stretched over 0 .. 254.
    {
        std::ofstream lut(dir + "/red.lut", std::ios::binary);
        for (int c = 0; c < 3; ++c)
            for (int i = 0; i < 256; ++i) lut.put(char(c == 0 ? i : 0));
    }
    run = volren("render '" + volume + "' -o '" + dir + "/lut.png' --tf '" + dir + "/red.lut'" + common);
    ASSERT_EQ(run.exitCode, 0) << run.output;
    img = readImage(dir + "/lut.png");
    EXPECT_GT(img.at(16, 16, 0), 0.3f);
    EXPECT_LT(img.at(16, 16, 1) + img.at(16, 16, 2), 0.02f);
    std::ofstream(dir + "/short.lut") << "1 2 3\n";
    run = volren("render '" + volume + "' -o '" + dir + "/x.png' --tf '" + dir + "/short.lut'");
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_NE(run.output.find(dir + "/short.lut"), std::string::npos) << run.output;
}

TEST(VolrenCli, RenderHonoursSizeFramesStatsAndTransferFunction)
{
    VOLREN_REQUIRE_SHARED_DATA();
    const std::string dir = tempDirectory();
    const std::string volume = sharedData("mri/ch2.nii.gz");
    // An opaque pure red TF: every pixel where a ray meets the box is exactly red.
    std::ofstream(dir + "/red.tf") << "0 255 0 0 255\n255 255 0 0 255\n";
    const CliRun run = volren("render '" + volume + "' -o '" + dir + "/out.png' --size 96x64 --frames 3 --stats '" +
                           dir + "/stats.json' --tf '" + dir + "/red.tf' --background 0,0,1 --ortho 400 --set jitter=off --set lighting=off");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    const Image img = readImage(dir + "/out.png");
    ASSERT_EQ(img.width, 96);
    ASSERT_EQ(img.height, 64);
    EXPECT_EQ(img.at(48, 32, 0), 1.0f);
    EXPECT_EQ(img.at(48, 32, 2), 0.0f);
    EXPECT_EQ(img.at(0, 0, 2), 1.0f) << "background colour in the corner";
    EXPECT_EQ(img.at(0, 0, 0), 0.0f);

    nlohmann::json stats = nlohmann::json::parse(std::ifstream(dir + "/stats.json"));
    EXPECT_EQ(stats["width"], 96);
    EXPECT_EQ(stats["height"], 64);
    ASSERT_EQ(stats["frames"].size(), 3u);
    int timed = 0;
    for (const auto& f : stats["frames"]) {
        EXPECT_GT(f["cpu_ms"].get<double>(), 0.0);
        EXPECT_GT(f["draw_ms"].get<double>(), 0.0);
        EXPECT_LE(f["draw_ms"].get<double>(), f["cpu_ms"].get<double>());
        // A GPU time is a time within the frame, or null where the query's value cannot be true
        // (llvmpipe's first frame returns one longer than the whole frame).
        if (f["gpu_ms"].is_null()) continue;
        ++timed;
        EXPECT_GT(f["gpu_ms"].get<double>(), 0.0);
        EXPECT_LE(f["gpu_ms"].get<double>(), f["cpu_ms"].get<double>());
    }
    EXPECT_GE(timed, 2) << "timer queries work on llvmpipe";
    ASSERT_EQ(stats["composition_keys"].size(), 1u);
    const std::string key = stats["composition_keys"][0];
    EXPECT_NE(key.find("Jitter=null;"), std::string::npos) << key;
    EXPECT_NE(key.find("RayTraversal=dvr_front_to_back;"), std::string::npos) << key;
}

TEST(VolrenCli, FloatOutputIsWrittenAsExrWithAlpha)
{
    VOLREN_REQUIRE_SHARED_DATA();
    const std::string dir = tempDirectory();
    const CliRun run = volren("render '" + sharedData("mri/ch2.nii.gz") + "' -o '" + dir + "/out.exr' --size 32x32");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    const Image img = readImage(dir + "/out.exr");
    ASSERT_EQ(img.channels, 4);
    EXPECT_GT(img.at(16, 16, 3), 0.5f);
    EXPECT_EQ(img.at(0, 0, 3), 0.0f);
}

TEST(VolrenCli, ScaleBarAndAxesAreDrawnInTheirCornersOnlyWhenAsked)
{
    // The confocal stack's unit is the micron (ImageJ unit=micron): its bar's label says µm; the
    // image away from the bottom corners is the one without annotations.
    VOLREN_REQUIRE_SHARED_DATA();
    const std::string dir = tempDirectory();
    const std::string input = "'" + sharedData("microscopy/xyzc_16bit__dna_conf_wf.tif") + "' --size 160x160";
    ASSERT_EQ(volren("render " + input + " -o '" + dir + "/plain.png'").exitCode, 0);
    const CliRun run = volren("render " + input + " -o '" + dir + "/marked.png' --scale-bar --axes");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    const Image plain = readImage(dir + "/plain.png"), marked = readImage(dir + "/marked.png");
    ASSERT_EQ(marked.width, 160);
    int changedLeft = 0, changedRight = 0;
    for (int y = 0; y < 160; ++y)  // rows from the top
        for (int x = 0; x < 160; ++x) {
            bool same = true;
            for (int c = 0; c < 3; ++c) same = same && marked.at(x, y, c) == plain.at(x, y, c);
            if (y < 160 - 110) {
                ASSERT_TRUE(same) << x << "," << y << " (from the top)";
            } else {
                changedLeft += !same && x < 110;
                changedRight += !same && x >= 100;
            }
        }
    EXPECT_GT(changedLeft, 100) << "the axis gizmo";
    EXPECT_GT(changedRight, 40) << "the scale bar and its label";
    for (const char* bad : {"--scale-bar=1", "--axis-gizmo"}) EXPECT_EQ(volren("render " + input + " -o x.png " + bad).exitCode, 2);
}

TEST(VolrenCli, SamplesDrawIntoAMultisampledFramebuffer)
{
    // The instrument scene's rod at 4 samples per pixel: its edges blend with what lies behind,
    // so pixels of blended colour appear that a single-sampled frame lacks; the rest agrees.
    VOLREN_REQUIRE_SHARED_DATA();
    const std::string dir = tempDirectory();
    const std::string scene = std::string(VOLREN_SOURCE_DIR) + "/scenes/ct-instrument.osgt";
    for (const char* samples : {"1", "4"}) {
        const CliRun run = volren("render '" + scene + "' -o '" + dir + "/s" + samples + ".exr' --size 160x120 --samples " +
                                  samples);
        ASSERT_EQ(run.exitCode, 0) << run.output;
    }
    const Image one = readImage(dir + "/s1.exr"), four = readImage(dir + "/s4.exr");
    ASSERT_EQ(one.width, four.width);
    int differ = 0, alike = 0;
    for (int y = 0; y < one.height; ++y)
        for (int x = 0; x < one.width; ++x) {
            float d = 0.0f;
            for (int c = 0; c < 4; ++c) d = std::max(d, std::abs(one.at(x, y, c) - four.at(x, y, c)));
            differ += d > 0.05f;
            alike += d < 1e-3f;
        }
    EXPECT_GT(differ, 30) << "edges antialiased";
    EXPECT_GT(alike, one.width * one.height / 2) << "the rest as before";
}

TEST(VolrenCli, BenchWritesTheMatrixWithErrorsAgainstTheReference)
{
    // Two configurations of the default scene at 32x32: every output written, one row each, the
    // errors measured (finite, small, lighting off against its own unlit reference).
    VOLREN_REQUIRE_SHARED_DATA();
    const std::string dir = tempDirectory();
    // lighting=off draws another picture, so nothing can beat the default: --check-front passes.
    const CliRun run =
        volren("bench --size 32x32 --frames 1 --configs 'default;lighting=off' --check-front --out '" + dir + "/b'");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    for (const char* file : {"bench.md", "bench.csv", "bench.json"})
        EXPECT_TRUE(osgDB::fileExists(dir + "/b/" + file)) << file;
    std::ifstream csv(dir + "/b/bench.csv");
    std::string header, line;
    std::getline(csv, header);
    EXPECT_EQ(header.rfind("dataset,width,height,renderer,config,truth,frame_ms", 0), 0u) << header;
    const std::string tail = ",pareto,beats_default,light_move_ms,rebuild_ms,aux_bytes_per_voxel";
    EXPECT_EQ(header.substr(header.size() - tail.size()), tail) << header;
    int rows = 0;
    while (std::getline(csv, line)) {
        ++rows;
        // rmse is the 12th column: after the quoted dataset, config and truth.
        std::vector<std::string> fields;
        std::stringstream in(line);
        for (std::string f; std::getline(in, f, ',');) fields.push_back(f);
        ASSERT_EQ(fields.size(), 19u) << line;
        EXPECT_EQ(fields[15], "0") << "nothing beats the default: " << line;
        for (std::size_t k = 16; k < 19; ++k) EXPECT_EQ(fields[k], "-1") << "unshadowed rows measure no light moves: " << line;
        const double rmse = std::stod(fields[11]);
        EXPECT_GT(rmse, 0.0) << line;
        EXPECT_LT(rmse, 0.1) << line;
    }
    EXPECT_EQ(rows, 2);
    EXPECT_NE(run.output.find("reference 'unlit'"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("reference 'lit:diffuse + blinn-phong highlight'"), std::string::npos) << run.output;
}

/// The first number after `label` in `text` (-1 when absent).
double numberAfter(const std::string& text, const std::string& label)
{
    const std::size_t at = text.find(label);
    return at == std::string::npos ? -1.0 : std::stod(text.substr(at + label.size()));
}

TEST(VolrenCli, BenchMeasuresAgainstTheReferenceVolrenReferenceMakes)
{
    // The rod of ct-instrument is opaque geometry: bench's truth must end the rays at it and
    // composite over it, as `volren reference` does, so bench's error is what `volren compare`
    // reports for render against reference (the same view, tolerance and, by default in both,
    // central-difference normals).
    VOLREN_REQUIRE_SHARED_DATA();
    const std::string dir = tempDirectory();
    const std::string scene = std::string(VOLREN_SOURCE_DIR) + "/scenes/ct-instrument.osgt";
    const std::string size = " --size 48x40";
    const CliRun bench = volren("bench '" + scene + "'" + size +
                                " --frames 1 --configs default --tolerance 1e-4 --out '" + dir + "/b'");
    ASSERT_EQ(bench.exitCode, 0) << bench.output;
    ASSERT_EQ(volren("render '" + scene + "' -o '" + dir + "/gpu.exr'" + size).exitCode, 0);
    ASSERT_EQ(volren("reference '" + scene + "' -o '" + dir + "/truth.exr'" + size).exitCode, 0);
    const CliRun compare = volren("compare '" + dir + "/gpu.exr' '" + dir + "/truth.exr'");
    ASSERT_EQ(compare.exitCode, 0) << compare.output;
    const double compared = numberAfter(compare.output, "RMSE:");
    const double benched = numberAfter(bench.output, "default: ");  // "default: MS ms, RMSE R"
    const double rmse = numberAfter(bench.output.substr(bench.output.find("volren bench: default:")), "RMSE ");
    ASSERT_GT(benched, 0.0) << bench.output;
    ASSERT_GT(compared, 0.0) << compare.output;
    EXPECT_NEAR(rmse, compared, 1e-4 * compared) << bench.output << compare.output;
}

TEST(VolrenCli, SkippingLeavesEveryTraversalsImageOfARealCtBitIdentical)
{
    // The bonsai as `volren render` frames it at 256x256 with jittered rays, each traversal that
    // skips against acceleration=null. An isosurface march that stopped when a skip answered
    // exactly the ray's end lost the sample there and missed one silhouette pixel of 65,536
    // here (pixel 115,196): the answer covers samples before it, not at it.
    VOLREN_REQUIRE_SHARED_DATA();
    const std::string dir = tempDirectory();
    const std::string volume = sharedData("ct/bonsai.nii.gz");
    for (const char* traversal : {"isosurface", "dvr_front_to_back", "mip"}) {
        const std::string common = " --size 256x256 --set traversal=" + std::string(traversal);
        const std::string asked = std::string(traversal) == "mip" ? " --set acceleration=range" : "";  // MIP: when asked
        ASSERT_EQ(volren("render '" + volume + "' -o '" + dir + "/on.exr'" + common + asked).exitCode, 0);
        ASSERT_EQ(volren("render '" + volume + "' -o '" + dir + "/off.exr'" + common + " --set acceleration=null").exitCode, 0);
        const Image on = readImage(dir + "/on.exr"), off = readImage(dir + "/off.exr");
        ASSERT_EQ(on.pixels.size(), off.pixels.size());
        std::size_t differing = 0;
        for (std::size_t i = 0; i < on.pixels.size(); ++i) differing += on.pixels[i] != off.pixels[i];
        EXPECT_EQ(differing, 0u) << traversal;
        EXPECT_GT(coveredPixels(on), 2000.0f) << traversal;
    }
}

TEST(VolrenCli, AVolumeOverItsMemoryBudgetIsBrickedAndStatsSayWhatThePoolHolds)
{
    // The bonsai (256^3, 8-bit as 16-bit texels on llvmpipe: 32 MiB) within 1 MiB in bricks of
    // 16 voxels (18^3 texels of 2 bytes: 89 slots): only levels 2 and coarser fit, so the image
    // is the single texture's at lod 2.
    VOLREN_REQUIRE_SHARED_DATA();
    const std::string dir = tempDirectory();
    const std::string volume = sharedData("ct/bonsai.nii.gz");
    const std::string common = " --size 96x96 --set texturePrecision=16bit";
    const CliRun run = volren("render '" + volume + "' -o '" + dir + "/bricked.exr'" + common +
                              " --set memoryBudgetMB=1 --set brickSize=16 --stats '" + dir + "/stats.json'");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    ASSERT_EQ(volren("render '" + volume + "' -o '" + dir + "/lod2.exr'" + common + " --set lod=2").exitCode, 0);
    const nlohmann::json stats = nlohmann::json::parse(std::ifstream(dir + "/stats.json"));
    EXPECT_NE(stats["composition_keys"][0].get<std::string>().find("VolumeStorage=bricked"), std::string::npos);
    ASSERT_EQ(stats["bricked_volumes"].size(), 1u) << stats.dump();
    const nlohmann::json& b = stats["bricked_volumes"][0];
    EXPECT_EQ(b["level_sampled"], 2);
    EXPECT_LE(b["pool_bytes"].get<std::size_t>(), std::size_t(1) << 20);
    EXPECT_GT(b["bricks_resident"].get<std::size_t>(), 8u);
    EXPECT_EQ(b["bricks_missing"], 16 * 16 * 16 + 8 * 8 * 8) << "levels 0 and 1 left out";
    const Image bricked = readImage(dir + "/bricked.exr"), level2 = readImage(dir + "/lod2.exr");
    ASSERT_EQ(bricked.pixels.size(), level2.pixels.size());
    float worst = 0.0f;
    for (std::size_t i = 0; i < bricked.pixels.size(); ++i) worst = std::max(worst, std::abs(bricked.pixels[i] - level2.pixels[i]));
    EXPECT_LE(worst, 1e-4f);
    EXPECT_GT(coveredPixels(level2), 500.0f);
}

TEST(VolrenCli, AFileOpenedLazilyRendersItsFullResolutionFromBricksReadOnDemand)
{
    // A 96 x 80 x 64 16-bit NRRD (raw encoding) opened lazily with a RAM budget of 0.1 MiB keeps
    // only a coarse level in memory; its bricks of level 0 are read from the file as the frame
    // plans them, so the image equals the bricked render of the volume read whole, waiting or
    // streaming, and --stats counts the bricks read.
    const std::string dir = tempDirectory();
    const std::string file = dir + "/field.nrrd";
    {
        std::ofstream out(file, std::ios::binary);
        out << "NRRD0004\ntype: uint16\ndimension: 3\nsizes: 96 80 64\nspacings: 1 1 1.5\nencoding: raw\nendian: little\n\n";
        for (int z = 0; z < 64; ++z)
            for (int y = 0; y < 80; ++y)
                for (int x = 0; x < 96; ++x) {
                    const double r = std::hypot(x - 48.0, y - 40.0, 1.5 * (z - 32.0));
                    const auto v = std::uint16_t(r < 36.0 ? 30000.0 + 20000.0 * std::sin(0.4 * x) * std::cos(0.3 * y + 0.2 * z) : 1000.0);
                    const unsigned char bytes[2] = {std::uint8_t(v & 0xff), std::uint8_t(v >> 8)};
                    out.write(reinterpret_cast<const char*>(bytes), 2);
                }
    }
    // One TF for all (a default TF would come from each volume's histogram: the preview's when lazy).
    std::ofstream(dir + "/field.tf") << "0 0 0 0 0\n5000 0 0 0 0\n20000 60 120 255 20\n40000 255 200 120 60\n65535 255 255 255 120\n";
    // The view the default framing gave before it fitted the box tightly. Open: trilinear samples
    // of the file's bricks differ from the in-memory volume's by ~1e-5 in every view (nearest: 0);
    // the tight default view puts one pixel on an edge where that grows to 8.3e-4.
    const std::string common = " --size 80x80 --set brickSize=16 --set volumestorage=bricked --set jitter=off"
                               " --eye 143,260,91 --center 0,0,0 --tf '" + dir + "/field.tf'";
    ASSERT_EQ(volren("render '" + file + "' -o '" + dir + "/whole.exr'" + common).exitCode, 0);
    const CliRun lazy = volren("render '" + file + "' -o '" + dir + "/lazy.exr'" + common + " -O ramBudgetMB=0.1 --stats '" +
                               dir + "/stats.json'");
    ASSERT_EQ(lazy.exitCode, 0) << lazy.output;
    const CliRun streamed = volren("render '" + file + "' -o '" + dir + "/streamed.exr'" + common +
                                   " -O lazy -O ramBudgetMB=0.1 --set streamBricks=on --set uploadBudgetMB=0.05 --stats '" + dir +
                                   "/streamed.json'");
    ASSERT_EQ(streamed.exitCode, 0) << streamed.output;
    const nlohmann::json stats = nlohmann::json::parse(std::ifstream(dir + "/stats.json"));
    ASSERT_EQ(stats["bricked_volumes"].size(), 1u) << stats.dump();
    const nlohmann::json& b = stats["bricked_volumes"][0];
    EXPECT_EQ(b["level_sampled"], 0);
    EXPECT_GT(b["bricks_loaded"].get<std::size_t>(), 6u * 5 * 4 / 2) << "level 0 read brick by brick";
    EXPECT_EQ(b["bricks_pending"], 0);
    EXPECT_GT(b["source_ram_bytes"].get<std::size_t>(), 0u);
    EXPECT_LT(b["source_ram_bytes"].get<std::size_t>(), std::size_t(96 * 80 * 64 * 2) / 8) << "a coarse level only";
    const nlohmann::json s = nlohmann::json::parse(std::ifstream(dir + "/streamed.json"));
    EXPECT_GT(s["streamed_frames"].get<int>(), 1) << "0.05 MiB a frame: several frames until converged";
    const Image whole = readImage(dir + "/whole.exr"), fromFile = readImage(dir + "/lazy.exr"),
                stream = readImage(dir + "/streamed.exr");
    ASSERT_EQ(whole.pixels.size(), fromFile.pixels.size());
    ASSERT_EQ(whole.pixels.size(), stream.pixels.size());
    float worst = 0.0f, worstStream = 0.0f;
    for (std::size_t i = 0; i < whole.pixels.size(); ++i) {
        worst = std::max(worst, std::abs(whole.pixels[i] - fromFile.pixels[i]));
        worstStream = std::max(worstStream, std::abs(whole.pixels[i] - stream.pixels[i]));
    }
    EXPECT_LE(worst, 1e-4f);
    EXPECT_LE(worstStream, 1e-4f);
    EXPECT_GT(coveredPixels(whole), 800.0f);

    const CliRun info = volren("info '" + file + "' -O lazy -O ramBudgetMB=0.1");
    ASSERT_EQ(info.exitCode, 0) << info.output;
    EXPECT_NE(info.output.find("opened lazily: 96 x 80 x 64 voxels in the file"), std::string::npos) << info.output;
}

TEST(VolrenCli, TheDefaultViewDrawsOnePictureFromNanometreToHugeSpacings)
{
    // A float soft ball at spacings 1e-9 to 1e12, framed by the default camera: the same picture.
    // The default projection's planes were fixed at 0.01 and 1e6, and OSG's near/far rescaling
    // of that projection lost everything to rounding at spacing 1e12 (a black image).
    const std::string dir = tempDirectory();
    auto write = [&dir](const std::string& name, double spacing) {
        std::ofstream out(dir + "/" + name, std::ios::binary);
        out << "NRRD0004\ntype: float\ndimension: 3\nsizes: 16 16 16\nspacings: " << spacing << " " << spacing << " " << spacing
            << "\nencoding: raw\nendian: little\n\n";
        for (int z = 0; z < 16; ++z)
            for (int y = 0; y < 16; ++y)
                for (int x = 0; x < 16; ++x) {
                    const float v = float(std::max(0.0, 1.0 - std::hypot(x - 7.5, y - 7.5, z - 7.5) / 8.0));
                    out.write(reinterpret_cast<const char*>(&v), sizeof(v));
                }
    };
    write("unit.nrrd", 1.0);
    ASSERT_EQ(volren("render '" + dir + "/unit.nrrd' -o '" + dir + "/unit.exr' --size 48x48").exitCode, 0);
    const Image unit = readImage(dir + "/unit.exr");
    float covered = 0.0f;
    for (std::size_t i = 3; i < unit.pixels.size(); i += 4) covered += unit.pixels[i] > 0.05f;
    ASSERT_GT(covered, 300.0f);
    for (double spacing : {1e-9, 1e8, 1e12}) {
        write("scaled.nrrd", spacing);
        ASSERT_EQ(volren("render '" + dir + "/scaled.nrrd' -o '" + dir + "/scaled.exr' --size 48x48").exitCode, 0);
        const Image scaled = readImage(dir + "/scaled.exr");
        ASSERT_EQ(scaled.pixels.size(), unit.pixels.size());
        float worst = 0.0f;
        for (std::size_t i = 0; i < unit.pixels.size(); ++i) worst = std::max(worst, std::abs(unit.pixels[i] - scaled.pixels[i]));
        EXPECT_LT(worst, 2e-3f) << "spacing " << spacing;
    }
}

TEST(VolrenCli, OneTextureBeyondTheLargest3DTextureIsRefusedNotShrunk)
{
    // 4096 voxels along x exceed llvmpipe's largest 3D texture (2048). The policy draws such a
    // volume from bricks; forced into one texture, OSG used to shrink it silently (a wrong
    // picture, RMSE 0.026 against the bricks, exit 0). Now the command fails naming the file.
    const std::string dir = tempDirectory();
    {
        std::ofstream out(dir + "/wide.nrrd", std::ios::binary);
        out << "NRRD0004\ntype: float\ndimension: 3\nsizes: 4096 4 4\nspacings: 0.01 1 1\nencoding: raw\nendian: little\n\n";
        for (int i = 0; i < 4096 * 16; ++i) {
            const float v = float((i * 7919) % 101) / 100.0f;
            out.write(reinterpret_cast<const char*>(&v), sizeof(v));
        }
    }
    const CliRun forced = volren("render '" + dir + "/wide.nrrd' -o '" + dir + "/texture.exr' --size 32x32 --set volumeStorage=texture");
    EXPECT_EQ(forced.exitCode, 1) << forced.output;
    EXPECT_NE(forced.output.find("wide.nrrd"), std::string::npos) << forced.output;
    EXPECT_NE(forced.output.find("is 4096x4x4 texels at level 0, beyond this driver's largest 3D texture"), std::string::npos)
        << forced.output;
    const CliRun chosen = volren("render '" + dir + "/wide.nrrd' -o '" + dir + "/bricked.exr' --size 32x32");
    EXPECT_EQ(chosen.exitCode, 0) << chosen.output;
}

TEST(VolrenCli, InfoPrintsGeometryAndValues)
{
    VOLREN_REQUIRE_SHARED_DATA();
    const CliRun run = volren("info '" + sharedData("ct/CT_AVM.nii.gz") + "'");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_NE(run.output.find("dims:        256 x 242 x 154"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("voxel type:  uint8"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("spacing:     0.7199"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("blocks:      1 channel x 1 time point"), std::string::npos) << run.output;

    const CliRun stack = volren("info '" + sharedData("microscopy/xyzc_16bit__dna_conf_wf.tif") + "'");
    ASSERT_EQ(stack.exitCode, 0) << stack.output;
    EXPECT_NE(stack.output.find("dims:        133 x 130 x 45"), std::string::npos) << stack.output;
    EXPECT_NE(stack.output.find("blocks:      2 channels x 1 time point"), std::string::npos) << stack.output;
}

TEST(VolrenCli, ImplementationsComeFromPluginLibrariesAndShaderFoldersAtRunTime)
{
    const std::string env = std::string("VOLREN_FUNCTION_PATH='") + VOLREN_TEST_PLUGIN_DIR + "' VOLREN_SHADER_PATH='" +
                            VOLREN_TEST_SHADER_DIR + "' ";
    const std::string dir = tempDirectory();
    CliRun run = volren("--help-settings");
    EXPECT_EQ(run.output.find("plugin_constant"), std::string::npos) << "not there without the paths";
    run = volren("--help-settings", ".", env);
    EXPECT_NE(run.output.find("plugin_constant"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("directory_quarter"), std::string::npos) << run.output;

    run = volren("shader --set jitter=plugin_constant", ".", env);
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_NE(run.output.find("uniform float volren_pluginJitter;"), std::string::npos);
    EXPECT_NE(run.output.find("// ---- Jitter/plugin_constant.glsl ----"), std::string::npos);
    EXPECT_NE(run.output.find("Jitter=plugin_constant;"), std::string::npos);

    run = volren("render -o '" + dir + "/q.png' --size 32x32 --set jitter=directory_quarter", ".", env);
    EXPECT_EQ(run.exitCode, 0) << run.output;
    run = volren("render -o '" + dir + "/q.png' --size 32x32 --set jitter=directory_quarter");
    EXPECT_EQ(run.exitCode, 2) << "unknown without the folder";
    EXPECT_NE(run.output.find("slot Jitter has no implementation 'directory_quarter'"), std::string::npos) << run.output;
}

TEST(VolrenCli, ShaderPrintsTheComposedSourceWithItsFiles)
{
    const CliRun run = volren("shader --set traversal=mip --set reconstruction=tricubic");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_NE(run.output.find("// ===== key: Reconstruction=tricubic;"), std::string::npos) << run.output.substr(0, 400);
    for (const char* file : {"// ---- RayTraversal/mip.glsl ----", "// ---- Reconstruction/tricubic.glsl ----",
                             "// ---- slots.glsl ----", "// ---- RaySetup/box_intersection.glsl ----"})
        EXPECT_NE(run.output.find(file), std::string::npos) << file;
    EXPECT_EQ(run.output.find("Shading/lights.glsl"), std::string::npos) << "MIP does not shade";
}

TEST(VolrenCli, HelpSettingsListsEveryKeyAndImplementation)
{
    const CliRun run = volren("render --help-settings");
    ASSERT_EQ(run.exitCode, 0);
    for (const char* text : {"samplerate", "earlyTermination", "lighting", "traversal", "isoValue",
                             "RayTraversal    (traversal): dvr_front_to_back", "cook_torrance", "central9", "tricubic"})
        EXPECT_NE(run.output.find(text), std::string::npos) << text;
}

TEST(VolrenCli, ConvertWritesNrrdThatReadsBackIdentically)
{
    VOLREN_REQUIRE_SHARED_DATA();
    const std::string dir = tempDirectory();
    const std::string input = sharedData("mri/HeadMRVolume.mhd");
    CliRun run = volren("convert '" + input + "' '" + dir + "/head.nrrd'");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_NE(run.output.find("48 x 62 x 42 uint8, 1 channel"), std::string::npos) << run.output;
    const osg::ref_ptr<Volume> original = readVolumeFile(input);
    const osg::ref_ptr<Volume> converted = readVolumeFile(dir + "/head.nrrd");
    EXPECT_EQ(converted->type(), original->type());
    expectSameVoxels(*converted, *original);

    run = volren("convert '" + input + "'");
    EXPECT_EQ(run.exitCode, 2) << run.output;
    run = volren("convert '" + input + "' '" + dir + "/noextension'");
    EXPECT_EQ(run.exitCode, 2) << run.output;
    EXPECT_NE(run.output.find("needs an extension"), std::string::npos) << run.output;
    run = volren("convert '" + dir + "/missing.nii' '" + dir + "/x.nrrd'");
    EXPECT_EQ(run.exitCode, 1) << run.output;
    EXPECT_NE(run.output.find(dir + "/missing.nii: no such file"), std::string::npos) << run.output;
    run = volren("convert '" + input + "' '" + dir + "/x.unknownformat'");
    EXPECT_EQ(run.exitCode, 1) << run.output;
    EXPECT_NE(run.output.find(dir + "/x.unknownformat"), std::string::npos) << run.output;
}

TEST(VolrenCli, ConvertWritesAnOmeZarrPyramidThatReadsBack)
{
    VOLREN_REQUIRE_SHARED_DATA();
    const std::string dir = tempDirectory();
    const std::string input = sharedData("mri/HeadMRVolume.mhd");  // 48 x 62 x 42 uint8, spacing 4
    CliRun run = volren("convert '" + input + "' '" + dir + "/head.ome.zarr' -O chunk=16 -O compression=zlib");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_NE(run.output.find("48 x 62 x 42 uint8, 1 channel"), std::string::npos) << run.output;
    const osg::ref_ptr<Volume> original = readVolumeFile(input);
    const osg::ref_ptr<Volume> converted = readVolumeFile(dir + "/head.ome.zarr");
    expectSameVoxels(*converted, *original);
    // 48x62x42 -> 24x31x21 -> 12x16x11: levels until every axis fits one 16-voxel chunk.
    int levels = 0;
    EXPECT_TRUE(converted->getUserValue("omeZarrLevels", levels));
    EXPECT_EQ(levels, 3);
    std::ifstream zarray(dir + "/head.ome.zarr/0/.zarray");
    const nlohmann::json meta = nlohmann::json::parse(zarray);
    EXPECT_EQ(meta["chunks"], nlohmann::json({16, 16, 16}));
    EXPECT_EQ(meta["compressor"]["id"], "zlib");

    run = volren("convert '" + input + "' '" + dir + "/x.ome.zarr' -O");
    EXPECT_EQ(run.exitCode, 2) << run.output;
    run = volren("convert '" + input + "' '" + dir + "/x.ome.zarr' -O compression=lzma");
    EXPECT_EQ(run.exitCode, 1) << run.output;
    EXPECT_NE(run.output.find(dir + "/x.ome.zarr: option compression=lzma"), std::string::npos) << run.output;
    EXPECT_FALSE(std::filesystem::exists(dir + "/x.ome.zarr"));
}

TEST(VolrenCli, BadArgumentsExitWithUsageErrors)
{
    VOLREN_REQUIRE_SHARED_DATA();
    const std::string dir = tempDirectory();
    const std::string volume = sharedData("mri/ch2.nii.gz");
    struct Case { std::string args, expect; int code; };
    for (const Case& c : {Case{"frobnicate", "unknown command 'frobnicate'", 2},
                          Case{"render '" + volume + "'", "missing -o OUT", 2},
                          Case{"render '" + volume + "' -o x.png --size 12", "--size: expected WxH", 2},
                          Case{"render '" + volume + "' -o x.png --size 0x5", "--size width", 2},
                          Case{"render '" + volume + "' -o x.png --fov 30 --ortho 4", "exclude each other", 2},
                          Case{"render '" + volume + "' -o x.png --eye 1,2", "--eye: expected x,y,z", 2},
                          Case{"render '" + volume + "' -o x.png --set warp=9", "unknown setting 'warp'", 2},
                          Case{"render '" + volume + "' -o x.png --set traversal=xray", "no implementation 'xray'", 2},
                          Case{"render '" + volume + "' -o x.png --set lighting=dim", "lighting must be on or off", 2},
                          Case{"render '" + volume + "' -o x.png --set samplerate=0", "samplerate must be", 2},
                          Case{"render '" + volume + "' -o x.png --frames -1", "--frames", 2},
                          Case{"render '" + volume + "' -o x.png --samples 0", "--samples: '0' must be a whole number in 1..64", 2},
                          Case{"render '" + volume + "' -o x.png --samples 64", "64 samples asked, the driver offers at most", 1},
                          Case{"render '" + volume + "' -o x.png --bogus", "unknown option '--bogus'", 2},
                          Case{"render " + dir + "/none.nii -o x.png", dir + "/none.nii: no such file", 1},
                          Case{"render '" + volume + "' -o x.png --tf " + dir + "/none.tf", dir + "/none.tf: cannot open", 1},
                          Case{"render '" + volume + "' -o " + dir + "/x.unknownformat", "x.unknownformat", 1},
                          Case{"info", "info takes exactly one volume file", 2}}) {
        const CliRun run = volren(c.args, dir);
        EXPECT_EQ(run.exitCode, c.code) << c.args << "\n" << run.output;
        EXPECT_NE(run.output.find(c.expect), std::string::npos) << c.args << "\n" << run.output;
    }
}

TEST(VolrenCli, EveryCommandHasHelpAndUnknownOptionsShowThatCommandsUsage)
{
    const CliRun version = volren("--version");
    EXPECT_EQ(version.exitCode, 0);
    EXPECT_EQ(version.output, std::string("volren ") + VOLREN_VERSION_TEXT + "\n");
    const CliRun all = volren("--help");
    EXPECT_EQ(all.exitCode, 0);
    for (const char* command : {"render", "reference", "compare", "info", "convert", "view", "shader", "bench", "permutations"}) {
        const CliRun help = volren(std::string(command) + " --help");
        EXPECT_EQ(help.exitCode, 0) << command << "\n" << help.output;
        const std::string own = std::string("volren ") + command + " ";
        EXPECT_NE(help.output.find(own), std::string::npos) << command << "\n" << help.output;
        EXPECT_NE(all.output.find(own), std::string::npos) << command;
        // Only that command's usage, not the whole list.
        const std::string other = std::string(command) == "info" ? "volren compare " : "volren info ";
        EXPECT_EQ(help.output.find(other), std::string::npos) << command << "\n" << help.output;
    }
    const CliRun bad = volren("view --bogus");
    EXPECT_EQ(bad.exitCode, 2);
    EXPECT_NE(bad.output.find("unknown option '--bogus'"), std::string::npos) << bad.output;
    EXPECT_NE(bad.output.find("volren view "), std::string::npos) << bad.output;
    EXPECT_EQ(bad.output.find("volren bench "), std::string::npos) << bad.output;
}

TEST(VolrenCli, ProgressInALogIsAStartLineAndAnEndLineNotRedraws)
{
    // Output to a pipe (as in CI logs): no carriage-return redraws, a start and an end line
    // (VOLREN_PROGRESS_DELAY=0 shows progress for this short load).
    const std::string dir = tempDirectory();
    {
        std::ofstream out(dir + "/ramp.nrrd", std::ios::binary);
        out << "NRRD0004\ntype: uint8\ndimension: 3\nsizes: 64 64 64\nencoding: raw\n\n";
        for (int i = 0; i < 64 * 64 * 64; ++i) out.put(char(i % 251));
    }
    const CliRun run = volren("info ramp.nrrd", dir, "VOLREN_PROGRESS_DELAY=0 ");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_EQ(run.output.find('\r'), std::string::npos) << run.output;
    const std::size_t start = run.output.find("loading ramp.nrrd ...\n"), end = run.output.find("loading ramp.nrrd: done in ");
    EXPECT_NE(start, std::string::npos) << run.output;
    EXPECT_NE(end, std::string::npos) << run.output;
    EXPECT_LT(start, end);
    EXPECT_EQ(volren("info ramp.nrrd", dir).output.find("loading ramp.nrrd"), std::string::npos) << "quick loads stay quiet";
}

}  // namespace
}  // namespace volren::test
