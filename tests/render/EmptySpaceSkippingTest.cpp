// Empty-space skipping (Acceleration occupancy) is invisible: every image with skipping is the
// image without it, bit for bit, for closed-form scenes, thin features at every macrocell size,
// every classification and reconstruction that allows it, both compositing directions, a camera
// inside an empty cell, transfer-function edits between frames and a real CT; and the value-range
// grid it rests on equals a brute-force reduction.
#include "AccelerationFixture.h"
#include "RenderFixture.h"
#include "TestData.h"

#include <volume_renderer/MacrocellGrid.h>
#include <volume_renderer/SampleDistance.h>
#include <volume_renderer/VolumeScene.h>

#include <volume_model/ReadVolume.h>

#include <glm/gtc/packing.hpp>
#include <osg/LightSource>
#include <osg/MatrixTransform>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

namespace volren::test {
namespace {

TEST(MacrocellGrid, RangesEqualABruteForceReductionWithTheApron)
{
    osg::ref_ptr<Volume> volume = new Volume;
    const osg::Vec3i d(19, 13, 10);  // not multiples of the cell size
    volume->allocate(VoxelType::UInt16, d);
    std::mt19937 random(7);
    auto* v = reinterpret_cast<std::uint16_t*>(volume->data());
    for (std::size_t i = 0; i < volume->voxelCount(); ++i) v[i] = std::uint16_t(random() % 65536);
    volume->dirty();
    for (int size : {1, 4, 5, 32})
        for (int apron : {0, 1, 2}) {
            const MacrocellGrid grid = buildMacrocellGrid(*volume, size, apron);
            ASSERT_EQ(grid.cells, osg::Vec3i((d.x() + size - 1) / size, (d.y() + size - 1) / size, (d.z() + size - 1) / size));
            for (int cz = 0; cz < grid.cells.z(); ++cz)
                for (int cy = 0; cy < grid.cells.y(); ++cy)
                    for (int cx = 0; cx < grid.cells.x(); ++cx) {
                        double lo = 1e9, hi = -1e9;
                        for (int z = std::max(0, cz * size - apron); z <= std::min(d.z() - 1, (cz + 1) * size - 1 + apron); ++z)
                            for (int y = std::max(0, cy * size - apron); y <= std::min(d.y() - 1, (cy + 1) * size - 1 + apron); ++y)
                                for (int x = std::max(0, cx * size - apron); x <= std::min(d.x() - 1, (cx + 1) * size - 1 + apron); ++x) {
                                    const double t = v[x + d.x() * (y + d.y() * z)] / 65535.0;
                                    lo = std::min(lo, t);
                                    hi = std::max(hi, t);
                                }
                        const std::size_t i = grid.index(cx, cy, cz);
                        ASSERT_FLOAT_EQ(grid.lo[i], float(lo)) << size << " " << apron;
                        ASSERT_FLOAT_EQ(grid.hi[i], float(hi)) << size << " " << apron;
                    }
        }
}

TEST(MacrocellGrid, NaNVoxelsAreLeftOutAndSignedTexelsFollowSnorm)
{
    osg::ref_ptr<Volume> floats = new Volume;
    floats->allocate(VoxelType::Float32, {4, 2, 2});
    auto* f = reinterpret_cast<float*>(floats->data());
    for (int i = 0; i < 16; ++i) f[i] = std::numeric_limits<float>::quiet_NaN();
    f[3] = 7.0f;  // cell x = 1 of a 2-voxel grid
    f[2] = std::numeric_limits<float>::infinity();
    floats->dirty();
    const MacrocellGrid grid = buildMacrocellGrid(*floats, 2, 0);
    EXPECT_GT(grid.lo[0], grid.hi[0]) << "a cell of NaN only has no range";
    EXPECT_EQ(grid.lo[1], 7.0f);
    EXPECT_EQ(grid.hi[1], std::numeric_limits<float>::infinity());
    EXPECT_EQ(occupancyOf(grid, [](double, double) { return true; }), (std::vector<std::uint8_t>{0, 255}));

    osg::ref_ptr<Volume> bytes = new Volume;
    bytes->allocate(VoxelType::Int8, {2, 1, 1});
    reinterpret_cast<std::int8_t*>(bytes->data())[0] = -128;
    reinterpret_cast<std::int8_t*>(bytes->data())[1] = 127;
    EXPECT_EQ(texelValue(*bytes, 0), -1.0);
    EXPECT_EQ(texelValue(*bytes, 1), 1.0);
    EXPECT_THROW(buildMacrocellGrid(*bytes, 0, 1), std::invalid_argument);
}

TEST(MacrocellGrid, TheCoarseLevelIsOccupiedWhereAnyOfItsCellsIs)
{
    osg::ref_ptr<Volume> volume = new Volume;
    volume->allocate(VoxelType::UInt8, {45, 18, 9});  // 9 x 4 x 2 cells of 5 voxels
    const MacrocellGrid grid = buildMacrocellGrid(*volume, 5, 1);
    ASSERT_EQ(grid.cells, osg::Vec3i(9, 4, 2));
    std::vector<std::uint8_t> occupancy(grid.size(), 0);
    occupancy[grid.index(8, 0, 1)] = 255;  // the last cell along x, alone in its coarse cell
    occupancy[grid.index(1, 3, 0)] = 255;
    osg::Vec3i size;
    const std::vector<std::uint8_t> texels = occupancyTexels(grid, occupancy, size);
    const int f = occupancyCoarseFactor;
    ASSERT_EQ(size, osg::Vec3i(9 + (9 + f - 1) / f, 4, 2));
    auto texel = [&](int x, int y, int z) { return texels[std::size_t(x) + std::size_t(size.x()) * (y + std::size_t(size.y()) * z)]; };
    int occupiedCoarse = 0;
    for (int z = 0; z < 2; ++z)
        for (int y = 0; y < 4; ++y)
            for (int x = 0; x < size.x(); ++x) {
                if (x < 9) {
                    EXPECT_EQ(texel(x, y, z), occupancy[grid.index(x, y, z)]);
                } else if (y < (4 + f - 1) / f && z < (2 + f - 1) / f) {
                    const int cx = x - 9;
                    const bool expected = (cx == 8 / f && y == 0 && z == 0) || (cx == 1 / f && y == 3 / f && z == 0);
                    EXPECT_EQ(texel(x, y, z), expected ? 255 : 0) << x << " " << y << " " << z;
                    occupiedCoarse += expected;
                } else {
                    EXPECT_EQ(texel(x, y, z), 0);
                }
            }
    EXPECT_EQ(occupiedCoarse, 2);
}

TEST(MacrocellGrid, HalfFloatBoundsRoundOutwards)
{
    std::mt19937 random(3);
    std::uniform_real_distribution<float> value(-70000.0f, 70000.0f);
    for (int i = 0; i < 20000; ++i) {
        const float v = i < 10000 ? value(random) : value(random) * 1e-6f;  // large and tiny
        const float lo = glm::unpackHalf1x16(halfBound(v, false)), hi = glm::unpackHalf1x16(halfBound(v, true));
        ASSERT_LE(lo, v) << v;
        ASSERT_GE(hi, v) << v;
        if (std::abs(v) < 60000.0f) {  // one half step apart at most
            ASSERT_LE(hi - lo, std::abs(v) * 2e-3f + 1.2e-7f) << v;
        }
    }
    for (float v : {0.0f, 1.0f, -1.0f, 200.0f / 255.0f, 1.0f / 65535.0f}) {
        EXPECT_LE(glm::unpackHalf1x16(halfBound(v, false)), v);
        EXPECT_GE(glm::unpackHalf1x16(halfBound(v, true)), v);
    }
    EXPECT_EQ(glm::unpackHalf1x16(halfBound(std::numeric_limits<float>::infinity(), true)), std::numeric_limits<float>::infinity());
    EXPECT_EQ(glm::unpackHalf1x16(halfBound(-std::numeric_limits<float>::infinity(), false)), -std::numeric_limits<float>::infinity());
    EXPECT_EQ(glm::unpackHalf1x16(halfBound(1e6f, true)), std::numeric_limits<float>::infinity());
    EXPECT_EQ(glm::unpackHalf1x16(halfBound(1e6f, false)), 65504.0f);
}

class EmptySpaceSkipping : public AccelerationFixture
{
};

TEST_F(EmptySpaceSkipping, AHomogeneousBlockInAnEmptyBoxIsBitIdenticalAndMatchesItsClosedForm)
{
    osg::ref_ptr<Volume> volume = bytes([](int x, int y, int z) {
        return x >= 10 && x < 20 && y >= 8 && y < 24 && z >= 12 && z < 22 ? 200 : 0;
    });
    // Nearest reconstruction keeps the block's faces sharp; the TF is constant over [101, 255].
    osg::ref_ptr<TransferFunction> tf = transferFunction(
        {{0, {0, 0, 0, 0}}, {100, {0, 0, 0, 0}}, {101, {1.0f, 0.6f, 0.2f, 0.1f}}, {255, {1.0f, 0.6f, 0.2f, 0.1f}}}, 0, 255);
    osg::ref_ptr<VolumeNode> node = volumeNode(volume.get(), tf.get());
    node->settings.functions["Reconstruction"] = "nearest";
    osg::ref_ptr<VolumeScene> scene = sceneOf(node.get());
    const auto [skipping, full] = withAndWithout(node.get(), scene.get(), [&] { return renderOrthoFromPlusZ(scene.get(), 32, 32, 32.0); });
    EXPECT_EQ(maxDifference(skipping, full), 0.0);
    EXPECT_TRUE(identical(skipping, full));
    // Through the block along z: 10 voxels of opacity 0.1 per voxel -> 1 - 0.9^10.
    const double expected = 1.0 - std::pow(0.9, 10.0);
    EXPECT_NEAR(skipping.at(15, 16).a(), expected, 2e-3);
    EXPECT_EQ(skipping.at(3, 3).a(), 0.0f) << "beside the block nothing is visible";

    // And it takes fewer samples: without skipping every ray takes one per step through the
    // 32 voxels (the closed form); with it, a ray beside the block's macrocells leaps the whole
    // box, and one through it samples the block's 10 voxels and the rest of its cells (measured:
    // 32 of 64 samples; 16,384 of 65,536 over the image).
    const auto [counted, every] =
        countsWithAndWithout(node.get(), scene.get(), [&] { return renderOrthoFromPlusZ(scene.get(), 32, 32, 32.0); });
    const double perRay = std::ceil(32.0 / effectiveSampleDistance(*node));
    EXPECT_EQ(every.at(3, 3).r(), perRay);
    EXPECT_EQ(every.at(15, 16).r(), perRay);
    EXPECT_EQ(samples(every), perRay * 32 * 32);
    EXPECT_LT(counted.at(3, 3).r(), 0.1 * perRay) << "an empty ray leaps the box";
    EXPECT_GE(counted.at(15, 16).r(), std::floor(10.0 / effectiveSampleDistance(*node))) << "the block is sampled";
    EXPECT_LT(counted.at(15, 16).r(), 0.6 * perRay);
    EXPECT_LE(samples(counted), 0.25 * samples(every));
}

TEST_F(EmptySpaceSkipping, AOneVoxelPlaneIsNeverSkippedAtAnyMacrocellSize)
{
    osg::ref_ptr<Volume> volume = bytes([](int, int, int z) { return z == 17 ? 255 : 0; });
    osg::ref_ptr<TransferFunction> tf =
        transferFunction({{0, {0, 0, 0, 0}}, {128, {0, 0, 0, 0}}, {255, {0.9f, 0.9f, 1.0f, 0.8f}}}, 0, 255);
    osg::ref_ptr<VolumeNode> node = volumeNode(volume.get(), tf.get());
    osg::ref_ptr<VolumeScene> scene = sceneOf(node.get());
    for (int size : {1, 2, 3, 4, 8, 16, 32, 64}) {
        node->settings.macrocellSize = size;
        for (const char* traversal : {"dvr_front_to_back", "dvr_back_to_front"}) {
            node->settings.functions["RayTraversal"] = traversal;
            const auto [skipping, full] = withAndWithout(node.get(), scene.get(), [&] { return oblique(scene.get()); });
            EXPECT_TRUE(identical(skipping, full)) << "cells of " << size << ", " << traversal << ": max difference "
                                                   << maxDifference(skipping, full);
            EXPECT_GT(covered(skipping), 300) << "the plane is visible";
        }
    }
}

TEST_F(EmptySpaceSkipping, EveryClassificationAndReconstructionThatAllowsItIsBitIdentical)
{
    osg::ref_ptr<Volume> volume = bytes([](int x, int y, int z) {
        const double r = std::sqrt((x - 15.5) * (x - 15.5) + (y - 14.0) * (y - 14.0) + (z - 17.0) * (z - 17.0));
        return r < 11.0 ? int(255.0 * std::max(0.0, 1.0 - std::abs(r - 8.0) / 3.0)) : 0;  // a soft shell
    });
    osg::ref_ptr<TransferFunction> tf =
        transferFunction({{0, {0, 0, 0, 0}}, {150, {0.2f, 0.4f, 0.9f, 0.0f}}, {255, {1.0f, 0.8f, 0.3f, 0.6f}}}, 0, 255);
    osg::ref_ptr<VolumeNode> node = volumeNode(volume.get(), tf.get(), true);  // jittered rays too
    for (bool lit : {false, true}) {
        osg::ref_ptr<VolumeScene> scene = sceneOf(node.get(), lit);
        for (const char* classification : {"tf1d", "premultiplied", "threshold", "null"})
            for (const char* reconstruction : {"nearest", "trilinear", "tricubic"}) {
                node->settings.functions["Classification"] = classification;
                node->settings.functions["Reconstruction"] = reconstruction;
                node->settings.parameters["threshold"] = 0.7;
                const auto [skipping, full] = withAndWithout(node.get(), scene.get(), [&] { return oblique(scene.get()); });
                EXPECT_TRUE(identical(skipping, full)) << classification << " " << reconstruction << (lit ? " lit" : "")
                                                       << ": max difference " << maxDifference(skipping, full);
                EXPECT_GT(covered(skipping), 150) << classification << " " << reconstruction;
            }
    }
}

TEST_F(EmptySpaceSkipping, ATransferFunctionThatHidesEverythingRendersExactlyTheBackground)
{
    osg::ref_ptr<Volume> volume = bytes([](int x, int y, int z) { return (x * 7 + y * 3 + z * 5) % 256; });
    osg::ref_ptr<TransferFunction> tf = constantTransferFunction({1, 1, 1, 0});
    osg::ref_ptr<VolumeNode> node = volumeNode(volume.get(), tf.get());
    osg::ref_ptr<VolumeScene> scene = sceneOf(node.get());
    const Pixels image = oblique(scene.get());
    EXPECT_EQ(chosenAcceleration(scene.get()), "occupancy");
    EXPECT_EQ(scene->hiddenVolumeCount(), 1u) << "a volume that cannot show anything is not drawn";
    for (const osg::Vec4& c : image.rgba) ASSERT_EQ(c, osg::Vec4(0.1f, 0.2f, 0.3f, 0.0f));
    // A TF edit that shows the values from 254 on draws it again.
    tf->assign(*transferFunction({{0, {0, 0, 0, 0}}, {254, {0, 0, 0, 0}}, {255, {1, 1, 1, 1}}}, 0, 255));
    const Pixels one = oblique(scene.get());
    EXPECT_EQ(scene->hiddenVolumeCount(), 0u);
    EXPECT_GT(covered(one), 0);
}

TEST_F(EmptySpaceSkipping, TransferFunctionEditsBetweenFramesNeverShowStaleOccupancy)
{
    // Two blocks of different values, large enough to hold whole macrocells of one value (so a
    // grid kept from the TF before would hide the block the edit shows): each TF shows one.
    osg::ref_ptr<Volume> volume = bytes([](int x, int y, int z) {
        if (x >= 2 && x < 14 && y >= 2 && y < 14 && z >= 2 && z < 30) return 80;
        if (x >= 16 && x < 31 && y >= 16 && y < 31 && z >= 2 && z < 30) return 220;
        return 0;
    });
    osg::ref_ptr<TransferFunction> tf = new TransferFunction;
    auto show = [&](double value) {
        tf->assign(*transferFunction({{0, {0, 0, 0, 0}}, {value - 20, {0, 0, 0, 0}}, {value, {1, 0.7f, 0.3f, 0.5f}},
                                      {value + 20, {0, 0, 0, 0}}, {255, {0, 0, 0, 0}}},
                                     0, 255));
    };
    const std::vector<double> edits = {80.0, 220.0, 80.0, 150.0, 220.0};
    // The images without skipping first, in a scene of their own; then the skipping scene draws
    // one frame per edit in consecutive frames, so it keeps its grid from frame to frame.
    std::vector<Pixels> expected;
    {
        osg::ref_ptr<VolumeNode> reference = volumeNode(volume.get(), tf.get());
        reference->settings.forceNull.insert("Acceleration");
        osg::ref_ptr<VolumeScene> full = sceneOf(reference.get());
        for (double value : edits) {
            show(value);
            expected.push_back(oblique(full.get()));
        }
    }
    osg::ref_ptr<VolumeNode> node = volumeNode(volume.get(), tf.get());
    node->settings.macrocellSize = 4;
    osg::ref_ptr<VolumeScene> scene = sceneOf(node.get());
    for (std::size_t i = 0; i < edits.size(); ++i) {
        show(edits[i]);
        const Pixels edited = oblique(scene.get());  // the frame of the edit
        EXPECT_EQ(chosenAcceleration(scene.get()), "occupancy");
        EXPECT_TRUE(identical(edited, expected[i]))
            << "TF at " << edits[i] << ": max difference " << maxDifference(edited, expected[i]);
        EXPECT_GT(covered(edited), 50);  // at 150: the blobs' trilinear rims
    }
    EXPECT_FALSE(identical(expected[0], expected[1])) << "the two TFs show different blobs";
}

TEST_F(EmptySpaceSkipping, ACameraInsideAnEmptyMacrocellSeesTheSameImage)
{
    osg::ref_ptr<Volume> volume = bytes([](int x, int y, int z) {
        return x > 20 && x < 28 && y > 20 && y < 28 && z > 3 && z < 28 ? 180 + (x + y + z) % 60 : 0;
    });
    osg::ref_ptr<TransferFunction> tf =
        transferFunction({{0, {0, 0, 0, 0}}, {170, {0, 0, 0, 0}}, {240, {0.9f, 0.5f, 0.2f, 0.4f}}}, 0, 255);
    osg::ref_ptr<VolumeNode> node = volumeNode(volume.get(), tf.get());
    osg::ref_ptr<VolumeScene> scene = sceneOf(node.get(), true);
    // The volume spans [-16, 16]^3 around the origin; the eye sits in an empty cell near a corner.
    for (const osg::Vec3d& eye : {osg::Vec3d(-12, -12, -3), osg::Vec3d(-2, -9, 10)}) {
        const auto [skipping, full] = withAndWithout(node.get(), scene.get(), [&] {
            const osg::Matrixd v = osg::Matrixd::lookAt(eye, osg::Vec3d(8, 8, 0), osg::Vec3d(0, 0, 1));
            return render(scene.get(), 48, 40, v, osg::Matrixd::perspective(70, 1.2, 0.05, 300), osg::Vec3(0.1f, 0.2f, 0.3f));
        });
        EXPECT_TRUE(identical(skipping, full)) << "max difference " << maxDifference(skipping, full);
        EXPECT_GT(covered(skipping), 100);
    }
}

TEST_F(EmptySpaceSkipping, ProjectionsAndIsosurfacesLeapWhatCannotPassTheirLevel)
{
    // A bright core and a dark hole in a medium: MIP's maximum is the core wherever a ray
    // meets it, MinIP's minimum the hole; the leaps after them skip most of each ray.
    osg::ref_ptr<Volume> volume = bytes([](int x, int y, int z) {
        const double core = (x - 12) * (x - 12) + (y - 18) * (y - 18) + (z - 16) * (z - 16);
        const double hole = (x - 22) * (x - 22) + (y - 12) * (y - 12) + (z - 14) * (z - 14);
        if (core < 16) return 250 - int(core);
        if (hole < 9) return 5 + int(hole);
        return 60 + (x * 7 + y * 13 + z * 3) % 90;  // a rough medium
    });
    osg::ref_ptr<TransferFunction> tf =
        transferFunction({{0, {0.1f, 0.2f, 0.9f, 1.0f}}, {120, {0.4f, 0.4f, 0.4f, 0.5f}}, {255, {1, 0.9f, 0.7f, 1.0f}}}, 0, 255);
    osg::ref_ptr<VolumeNode> node = volumeNode(volume.get(), tf.get(), true);
    osg::ref_ptr<VolumeScene> scene = sceneOf(node.get());
    node->settings.parameters["isoValue"] = 200.0;  // the core's surface
    for (const char* traversal : {"mip", "minip", "isosurface"})
        for (const char* reconstruction : {"nearest", "trilinear", "tricubic"})
            for (int size : {2, 8}) {
                node->settings.functions["RayTraversal"] = traversal;
                node->settings.functions["Reconstruction"] = reconstruction;
                node->settings.functions["Acceleration"] = "range";  // MIP leaps only when asked
                node->settings.macrocellSize = size;
                const auto [skipping, full] = withAndWithout(node.get(), scene.get(), [&] { return oblique(scene.get()); }, "range");
                EXPECT_TRUE(identical(skipping, full)) << traversal << " " << reconstruction << " cells of " << size
                                                       << ": max difference " << maxDifference(skipping, full);
                EXPECT_GT(covered(skipping), std::string(traversal) == "isosurface" ? 20 : 800) << traversal;
                // The leaps save samples: the counts (the pass's debug output) with and without.
                const auto [counted, every] =
                    countsWithAndWithout(node.get(), scene.get(), [&] { return oblique(scene.get()); }, "range");
                // (Measured: 2-11 % fewer; the rough medium leaves little to leap before the extremum.)
                EXPECT_LT(samples(counted), 0.99 * samples(every))
                    << traversal << " " << reconstruction << " cells of " << size << ": " << samples(counted) << " of "
                    << samples(every) << " samples";
            }
}

TEST_F(EmptySpaceSkipping, ARealCtWithASparseTransferFunctionIsBitIdentical)
{
    if (!sharedDataPresent()) GTEST_SKIP() << "shared data absent";
    osg::ref_ptr<Volume> volume = readVolumeFile(sharedData("ct/bonsai.nii.gz"));
    ASSERT_TRUE(volume.valid());
    const auto [lo, hi] = volume->valueRange();
    // Only the densest tenth of the range shows (the trunk and pot), the rest is empty.
    const double a = lo + 0.6 * (hi - lo), b = lo + 0.9 * (hi - lo);
    osg::ref_ptr<TransferFunction> tf =
        transferFunction({{lo, {0, 0, 0, 0}}, {a, {0, 0, 0, 0}}, {b, {0.9f, 0.8f, 0.6f, 0.7f}}, {hi, {1, 1, 1, 0.9f}}}, lo, hi);
    osg::ref_ptr<VolumeNode> node = volumeNode(volume.get(), tf.get(), true);
    osg::ref_ptr<VolumeScene> scene = sceneOf(node.get(), true);
    const osg::BoundingSphere bound = scene->getBound();
    node->settings.parameters["isoValue"] = double(b);
    for (const char* traversal : {"dvr_front_to_back", "dvr_back_to_front", "mip", "minip", "isosurface"}) {
        node->settings.functions["RayTraversal"] = traversal;
        const bool extremum = std::string(traversal).find("dvr") != 0;
        if (extremum) node->settings.functions["Acceleration"] = "range";  // MIP leaps only when asked
        else node->settings.functions.erase("Acceleration");
        const auto [skipping, full] = withAndWithout(node.get(), scene.get(), [&] {
            const osg::Vec3d centre = bound.center();
            const osg::Matrixd v = osg::Matrixd::lookAt(centre + osg::Vec3d(1.2, -2.0, 1.0) * bound.radius(), centre,
                                                        osg::Vec3d(0, 0, 1));
            return render(scene.get(), 64, 64, v, osg::Matrixd::perspective(30, 1.0, 0.1 * bound.radius(), 10 * bound.radius()));
        }, extremum ? "range" : "occupancy");
        EXPECT_TRUE(identical(skipping, full)) << traversal << ": max difference " << maxDifference(skipping, full);
        if (std::string(traversal) != "minip") {  // MinIP finds the air
            EXPECT_GT(covered(skipping), std::string(traversal) == "isosurface" ? 30 : 300);
        }
    }
}

TEST_F(EmptySpaceSkipping, AMultiVolumeSetLeapsOnlyWhereEveryMemberIsEmpty)
{
    // Two overlapping volumes in one set, mostly empty: a block in one, a thin plane and a ball in
    // the other, placed so that rays meet each alone and both together. Each member skips its own
    // medium and the ray leaps only where every member is empty: the image is the one with the
    // members' Acceleration forced null, bit for bit, from the front and obliquely, with a camera
    // inside the overlap too; both traversal directions of the members.
    osg::ref_ptr<Volume> first = bytes([](int x, int y, int z) {
        return x >= 4 && x < 12 && y >= 10 && y < 22 && z >= 6 && z < 26 ? 180 : 0;
    });
    osg::ref_ptr<Volume> second = bytes([](int x, int y, int z) {
        const double r = std::sqrt((x - 20.0) * (x - 20.0) + (y - 12.0) * (y - 12.0) + (z - 16.0) * (z - 16.0));
        return z == 9 || r < 5.0 ? 230 : 0;
    });
    osg::ref_ptr<TransferFunction> warm =
        transferFunction({{0, {0, 0, 0, 0}}, {100, {0, 0, 0, 0}}, {255, {1.0f, 0.6f, 0.2f, 0.3f}}}, 0, 255);
    osg::ref_ptr<TransferFunction> cool =
        transferFunction({{0, {0, 0, 0, 0}}, {100, {0, 0, 0, 0}}, {255, {0.2f, 0.5f, 1.0f, 0.6f}}}, 0, 255);
    osg::ref_ptr<VolumeNode> a = volumeNode(first.get(), warm.get(), true);
    osg::ref_ptr<VolumeNode> b = volumeNode(second.get(), cool.get(), true);
    osg::ref_ptr<VolumeScene> scene = new VolumeScene;
    osg::ref_ptr<osg::MatrixTransform> moved = new osg::MatrixTransform(
        osg::Matrix::rotate(osg::DegreesToRadians(25.0), 0, 0, 1) * osg::Matrix::translate(7, 3, 2));
    moved->addChild(b.get());
    scene->addChild(a.get());
    scene->addChild(moved.get());
    auto both = [&](bool skip) {
        for (VolumeNode* n : {a.get(), b.get()}) {
            if (skip) n->settings.forceNull.erase("Acceleration");
            else n->settings.forceNull.insert("Acceleration");
        }
    };
    for (const char* traversal : {"dvr_front_to_back", "dvr_back_to_front"})
        for (const osg::Vec3d& eye : {osg::Vec3d(40, -55, 35), osg::Vec3d(-20, 70, -10), osg::Vec3d(3, 1, 2)}) {
            a->settings.functions["RayTraversal"] = traversal;
            b->settings.functions["RayTraversal"] = traversal;
            both(true);
            const Pixels skipping = oblique(scene.get(), eye, 70);
            const std::vector<std::string> keys = scene->compositionKeys();
            ASSERT_EQ(keys.size(), 1u);
            EXPECT_NE(keys.front().find("RayTraversal=sum_of_media"), std::string::npos) << keys.front();
            EXPECT_NE(keys.front().find("Acceleration=occupancy"), std::string::npos) << keys.front();
            both(false);
            const Pixels full = oblique(scene.get(), eye, 70);
            EXPECT_TRUE(identical(skipping, full)) << traversal << " from " << eye.x() << "," << eye.y() << ","
                                                   << eye.z() << ": max difference " << maxDifference(skipping, full);
            EXPECT_GT(covered(skipping), 40);
        }
    // A member whose TF hides everything keeps the set drawn for the other; when both hide
    // everything the set is not drawn at all.
    both(true);
    osg::ref_ptr<TransferFunction> none = constantTransferFunction({1, 1, 1, 0});
    a->setTransferFunction(none.get());
    const Pixels oneHidden = oblique(scene.get());
    EXPECT_EQ(scene->hiddenVolumeCount(), 0u);
    both(false);
    EXPECT_TRUE(identical(oneHidden, oblique(scene.get())));
    EXPECT_GT(covered(oneHidden), 40);
    both(true);
    b->setTransferFunction(none.get());
    const Pixels bothHidden = oblique(scene.get());
    EXPECT_EQ(scene->hiddenVolumeCount(), 1u);
    for (const osg::Vec4& c : bothHidden.rgba) ASSERT_EQ(c, osg::Vec4(0.1f, 0.2f, 0.3f, 0.0f));
}

}  // namespace
}  // namespace volren::test
