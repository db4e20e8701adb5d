// Jitter implementations.
#include <volume_renderer/ShaderFunctionRegistry.h>

#include <osg/Texture2D>

#include <random>

namespace volren {

namespace {

/// A 64x64 tile of uniform random numbers in [0,1), made once on first use (fixed seed).
osg::Texture2D* jitterTile()
{
    static osg::ref_ptr<osg::Texture2D> tile = [] {
        osg::ref_ptr<osg::Image> image = new osg::Image;
        image->allocateImage(64, 64, 1, GL_RED, GL_FLOAT);
        image->setInternalTextureFormat(GL_R32F);
        std::mt19937 rng(20261123);
        std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
        auto* values = reinterpret_cast<float*>(image->data());
        for (int i = 0; i < 64 * 64; ++i) values[i] = std::min(uniform(rng), 0.99999994f);
        osg::ref_ptr<osg::Texture2D> texture = new osg::Texture2D(image.get());
        texture->setInternalFormat(GL_R32F);
        texture->setResizeNonPowerOfTwoHint(false);
        texture->setFilter(osg::Texture::MIN_FILTER, osg::Texture::NEAREST);
        texture->setFilter(osg::Texture::MAG_FILTER, osg::Texture::NEAREST);
        texture->setWrap(osg::Texture::WRAP_S, osg::Texture::REPEAT);  // OSG's default CLAMP is not core GL
        texture->setWrap(osg::Texture::WRAP_T, osg::Texture::REPEAT);
        return texture;
    }();
    return tile.get();
}

}  // namespace

void registerJitterFunctions(ShaderFunctionRegistry& registry)
{
    const ImplementationTraits leaf{.calls = SlotList{}};
    registry.add({.slot = "Jitter", .name = "null", .traits = leaf, .reference = ReferenceModel::exact("no jitter"), .benchRows = {{}}});
    // Offsets of up to one step per ray: the same integral, sampled elsewhere.
    registry.add({.slot = "Jitter", .name = "hash", .traits = leaf, .reference = ReferenceModel::approximate("no jitter", 0.02)});
    registry.add({.slot = "Jitter",
                  .name = "texture",
                  .textures = {{"volren_jitterTexture", "sampler2D"}},
                  .bind = [](BindContext& c) { c.texture("volren_jitterTexture", jitterTile()); },
                  .traits = leaf,
                  .reference = ReferenceModel::approximate("no jitter", 0.02),
                  .benchRows = {{}}});
}

}  // namespace volren
