#include <volume_renderer/BindContext.h>

namespace volren {

const ClipInfo& BindContext::clip() const
{
    static const ClipInfo none;
    return instance >= 0 && std::size_t(instance) < clips.size() ? clips[std::size_t(instance)] : none;
}

void BindContext::texture(const std::string& base, osg::Texture* tex)
{
    auto unit = textureUnits.find(name(base));
    if (unit == textureUnits.end() || !tex) return;  // not used by this composition
    // Attribute only: shaders sample it; fixed-function texture modes are invalid in core profiles.
    stateSet.setTextureAttribute(unit->second, tex, osg::StateAttribute::ON);
    uniform(base, unit->second);
}

}  // namespace volren
