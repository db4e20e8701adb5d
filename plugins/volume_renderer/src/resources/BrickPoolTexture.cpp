// The brick pool's texture and its RAM mirror (BrickPoolTexture.h).
#include "BrickPoolTexture.h"

#include <volume_renderer/VolumeTextures.h>

#include <osg/GLExtensions>

#include <cstring>

namespace volren {

void BrickPoolMirror::write(int slot, const std::vector<std::uint8_t>& data)
{
    std::lock_guard<std::mutex> lock(mutex);
    std::memcpy(texels.get() + std::size_t(slot) * slotBytes, data.data(), slotBytes);
    used[std::size_t(slot)] = true;
    changes.emplace_back(++sequence, slot);
    if (changes.size() > 2 * used.size()) {  // a context stopped drawing: it reloads all if it comes back
        changes.clear();
        uploaded.clear();
    }
}

void BrickPoolMirror::upload(osg::State& state, bool all)
{
    std::lock_guard<std::mutex> lock(mutex);
    const unsigned int context = state.getContextID();
    auto it = uploaded.find(context);
    all = all || it == uploaded.end() || (!changes.empty() && it->second + 1 < changes.front().first);
    const osg::GLExtensions* gl = state.get<osg::GLExtensions>();
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    glPixelStorei(GL_UNPACK_IMAGE_HEIGHT, 0);
    auto send = [&](int s) {
        const int x = s % slots.x(), y = s / slots.x() % slots.y(), z = s / (slots.x() * slots.y());
        gl->glTexSubImage3D(GL_TEXTURE_3D, 0, x * slotTexels, y * slotTexels, z * slotTexels, slotTexels, slotTexels,
                            slotTexels, GL_RED, pixelType, texels.get() + std::size_t(s) * slotBytes);
    };
    if (all) {
        for (std::size_t s = 0; s < used.size(); ++s)
            if (used[s]) send(int(s));
    } else {
        for (const auto& [seq, slot] : changes)
            if (seq > it->second) send(slot);
    }
    uploaded[context] = sequence;
    unsigned long long oldest = sequence;
    for (const auto& [c, seq] : uploaded) oldest = std::min(oldest, seq);
    while (!changes.empty() && changes.front().first <= oldest) changes.pop_front();
}

namespace {

/// Allocates the pool's storage on a context's first use and sends it the bricks it lacks.
class PoolUpload : public osg::Texture3D::SubloadCallback
{
public:
    explicit PoolUpload(std::shared_ptr<BrickPoolMirror> mirror) : _mirror(std::move(mirror)) {}
    void load(const osg::Texture3D& texture, osg::State& state) const override
    {
        state.get<osg::GLExtensions>()->glTexImage3D(GL_TEXTURE_3D, 0, texture.getInternalFormat(), texture.getTextureWidth(),
                                                     texture.getTextureHeight(), texture.getTextureDepth(), 0, GL_RED,
                                                     _mirror->pixelType, nullptr);
        _mirror->upload(state, true);
    }
    void subload(const osg::Texture3D&, osg::State& state) const override { _mirror->upload(state, false); }

private:
    std::shared_ptr<BrickPoolMirror> _mirror;
};

}  // namespace

osg::ref_ptr<osg::Texture3D> makeBrickPoolTexture(std::shared_ptr<BrickPoolMirror> mirror, const osg::Vec3i& texels,
                                                  GLenum format)
{
    osg::ref_ptr<osg::Texture3D> pool = makeTexture3D(nullptr, format, osg::Texture::LINEAR);  // no image: the callback loads it
    pool->setTextureSize(texels.x(), texels.y(), texels.z());
    pool->setSubloadCallback(new PoolUpload(std::move(mirror)));
    return pool;
}

}  // namespace volren
