// volren::VolumeScene: the pass settings (`lighting`, `forceNullAll`), written as key/value
// pairs through PassSettings::keys()/get()/set() so new pass settings are saved without
// touching this file (those PassSettings::isSaved names: a debug output only while on). Children come from the osg::Group wrapper. `forcedComposition` is a
// testing hook (permutation sweeps) and is not saved.
#include "StreamFields.h"

#include <volume_renderer/VolumeScene.h>

#include <osgDB/ObjectWrapper>

#include <string>
#include <vector>

namespace {

using namespace volren::serializers;
using volren::VolumeScene;

bool checkPassSettings(const VolumeScene&) { return true; }

bool writePassSettings(osgDB::OutputStream& os, const VolumeScene& scene)
{
    std::vector<std::string> saved;
    for (const auto& entry : volren::PassSettings::keys())
        if (scene.pass.isSaved(entry.first)) saved.push_back(entry.first);
    writeInt(os, std::int64_t(saved.size()));
    os << os.BEGIN_BRACKET << std::endl;
    for (const std::string& key : saved) {
        os << key;  // an identifier: a bare word
        writeString(os, scene.pass.get(key));
        os << std::endl;
    }
    os << os.END_BRACKET << std::endl;
    return true;
}

bool readPassSettings(osgDB::InputStream& is, VolumeScene& scene)
{
    const std::string field = "volren::VolumeScene PassSettings";
    std::int64_t count = 0;
    if (!readInt(is, count, 0, 10000, field)) return false;
    is >> is.BEGIN_BRACKET;
    for (std::int64_t n = 0; n < count; ++n) {
        std::string key, value, error;
        if (!readString(is, key, field) || !readString(is, value, field + " " + key)) return false;
        if (!scene.pass.set(key, value, error)) return fail(is, field + ": " + error), false;
    }
    is >> is.END_BRACKET;
    return !is.getException();
}

}  // namespace

REGISTER_OBJECT_WRAPPER(volren_VolumeScene, new volren::VolumeScene, volren::VolumeScene,
                        "osg::Object osg::Node osg::Group volren::VolumeScene")
{
    ADD_USER_SERIALIZER(PassSettings);
}
