#pragma once
// The Acceleration suites' fixture: small byte volumes, an oblique view, images with and without
// an Acceleration, and their differences.
#include "RenderFixture.h"
#include "TestData.h"

#include <volume_renderer/VolumeScene.h>

#include <osg/LightSource>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <utility>

namespace volren::test {

/// Helpers of the Acceleration suites (empty-space skipping, adaptive sampling, LOD).
class AccelerationFixture : public RenderFixture
{
protected:
    /// A 32^3 byte volume of zeros (spacing 1) with `fill` applied.
    template <typename Fill>
    static osg::ref_ptr<Volume> bytes(Fill fill, int n = 32)
    {
        osg::ref_ptr<Volume> volume = new Volume;
        volume->allocate(VoxelType::UInt8, {n, n, n});
        for (int z = 0; z < n; ++z)
            for (int y = 0; y < n; ++y)
                for (int x = 0; x < n; ++x) volume->data()[x + n * (y + n * z)] = std::uint8_t(fill(x, y, z));
        volume->dirty();
        return volume;
    }

    static Pixels oblique(osg::Node* scene, const osg::Vec3d& eye = {40, -55, 35}, double fov = 35)
    {
        const osg::Matrixd v = osg::Matrixd::lookAt(eye, osg::Vec3d(), osg::Vec3d(0, 0, 1));
        return render(scene, 48, 40, v, osg::Matrixd::perspective(fov, 1.2, 0.05, 300), osg::Vec3(0.1f, 0.2f, 0.3f));
    }

    static osg::ref_ptr<VolumeScene> sceneOf(VolumeNode* node, bool lit = false)
    {
        osg::ref_ptr<VolumeScene> scene = new VolumeScene;
        scene->addChild(node);
        if (lit) {
            osg::ref_ptr<osg::LightSource> light = new osg::LightSource;
            light->getLight()->setPosition(osg::Vec4(0.3f, -0.5f, 1.0f, 0.0f));
            scene->addChild(light.get());
        }
        return scene;
    }

    static bool identical(const Pixels& a, const Pixels& b)
    {
        return a.rgba.size() == b.rgba.size() &&
               std::memcmp(a.rgba.data(), b.rgba.data(), a.rgba.size() * sizeof(osg::Vec4)) == 0;
    }

    static double maxDifference(const Pixels& a, const Pixels& b)
    {
        double worst = 0.0;
        for (std::size_t i = 0; i < a.rgba.size(); ++i)
            for (int c = 0; c < 4; ++c) worst = std::max(worst, double(std::abs(a.rgba[i][c] - b.rgba[i][c])));
        return worst;
    }

    static int covered(const Pixels& p)
    {
        int n = 0;
        for (const osg::Vec4& c : p.rgba) n += c.a() > 0.0f;
        return n;
    }

    /// The scene's image with the node's Acceleration as chosen (checked to be `expected`),
    /// then forced null; both returned.
    template <typename Render>
    static std::pair<Pixels, Pixels> withAndWithout(VolumeNode* node, VolumeScene* scene, Render draw,
                                                    const std::string& expected = "occupancy")
    {
        node->settings.forceNull.erase("Acceleration");
        Pixels skipping = draw();
        EXPECT_EQ(chosenAcceleration(scene), expected);
        node->settings.forceNull.insert("Acceleration");
        Pixels full = draw();
        node->settings.forceNull.erase("Acceleration");
        return {skipping, full};
    }

    /// The samples the scene's rays reconstruct, summed over the image drawn by `draw`, with the
    /// node's Acceleration as chosen (checked to be `expected`) and forced null: the pass's
    /// countSamples debug output, which writes each pixel's count into red.
    template <typename Render>
    static std::pair<Pixels, Pixels> countsWithAndWithout(VolumeNode* node, VolumeScene* scene, Render draw,
                                                          const std::string& expected = "occupancy")
    {
        scene->pass.countSamples = true;
        auto counts = withAndWithout(node, scene, draw, expected);
        scene->pass.countSamples = false;
        return counts;
    }

    /// The samples of every ray of a countSamples image: the sum of red over the pixels rays
    /// wrote (green and blue 0; the rest show the background).
    static double samples(const Pixels& counts)
    {
        double sum = 0.0;
        for (const osg::Vec4& c : counts.rgba)
            if (c.g() == 0.0f && c.b() == 0.0f) sum += c.r();
        return sum;
    }

    /// The Acceleration the scene chose for its first volume in the last frame.
    static std::string chosenAcceleration(VolumeScene* scene)
    {
        const std::vector<std::string> keys = scene->compositionKeys();
        if (keys.empty()) return {};
        const std::string tag = "Acceleration=";
        const std::size_t at = keys.front().find(tag);
        if (at == std::string::npos) return {};
        const std::size_t from = at + tag.size();
        return keys.front().substr(from, keys.front().find(';', from) - from);
    }
};

}  // namespace volren::test
