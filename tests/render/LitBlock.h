#pragma once
// The lit homogeneous block the Shadowing tests share: a block of spacing 1 lit by directional
// or point lights (Lambert, no ambient, no early termination), marched at half-voxel steps, and
// the closed form of its shadowed over its unshadowed emission seen from the light (+z).
#include "RenderFixture.h"

#include <osg/LightSource>

#include <cmath>
#include <functional>
#include <vector>

namespace volren::test {

class LitBlock : public RenderFixture
{
public:
    static constexpr int depthVoxels = 16;  ///< block depth along z (spacing 1)
    static constexpr double step = 0.5;     ///< view step (sampleFactor 0.5), also the shadow step
    static constexpr double alpha = 0.08;   ///< TF opacity of one reference segment (one voxel)
    static inline const double sigma = -std::log1p(-alpha);  ///< extinction per voxel

protected:
    /// `volume` lit by `lights` (Lambert, no ambient) with `shadowing`, light volume at `scale`.
    static osg::ref_ptr<VolumeScene> lit(Volume* volume, TransferFunction* tf, const char* shadowing, double scale = 1.0,
                                         const std::vector<osg::Vec4>& lights = {{0, 0, 1, 0}})
    {
        osg::ref_ptr<VolumeNode> node = volumeNode(volume, tf);
        node->settings.functions["Shading"] = "lighting";
        node->settings.functions["Illumination"] = "lambert";
        node->settings.functions["Shadowing"] = shadowing;
        node->settings.parameters["ambient"] = 0.0;
        node->settings.earlyTerminationThreshold = 1.0;
        node->settings.sampleDistanceFactor = step;
        node->settings.parameters["lightVolumeScale"] = double(scale);
        osg::ref_ptr<VolumeScene> scene = new VolumeScene;
        scene->addChild(node.get());
        for (std::size_t i = 0; i < lights.size(); ++i) {
            osg::ref_ptr<osg::LightSource> source = new osg::LightSource;
            source->getLight()->setLightNum(int(i));
            source->getLight()->setPosition(lights[i]);
            scene->addChild(source.get());
        }
        return scene;
    }

    /// Sum over the view ray's segments i from `first` (front first, each `step` long, in a
    /// depthVoxels-deep homogeneous block) of segment i's weight in the unshadowed image (times
    /// `weight(i)` where given) times `shadow(i)`, over the sum of the weights alone.
    static double expectedRatio(int first, const std::function<double(int)>& shadow,
                                const std::function<double(int)>& weight = {})
    {
        const double q = std::exp(-sigma * step);
        double lit = 0.0, unlit = 0.0, transmittance = 1.0;
        for (int i = first; i < int(depthVoxels / step); ++i) {
            const double w = transmittance * (1.0 - q) * (weight ? weight(i) : 1.0);
            lit += w * shadow(i);
            unlit += w;
            transmittance *= q;
        }
        return lit / unlit;
    }
};

}  // namespace volren::test
