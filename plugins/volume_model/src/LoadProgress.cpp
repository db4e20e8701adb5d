#include <volume_model/LoadProgress.h>

#include <algorithm>

namespace volren {

namespace {
const char* const key = "volren.loadProgress";
}

osg::ref_ptr<osgDB::Options> withLoadProgress(const osgDB::Options* base, const LoadProgress* progress)
{
    osg::ref_ptr<osgDB::Options> options =
        base ? static_cast<osgDB::Options*>(base->clone(osg::CopyOp::SHALLOW_COPY)) : new osgDB::Options;
    options->setPluginData(key, const_cast<LoadProgress*>(progress));
    return options;
}

const LoadProgress* loadProgressOf(const osgDB::Options* options)
{
    return options ? static_cast<const LoadProgress*>(options->getPluginData(key)) : nullptr;
}

bool reportLoadProgress(const osgDB::Options* options, double done, double total)
{
    const LoadProgress* progress = loadProgressOf(options);
    if (!progress || !*progress) return true;
    return (*progress)(total > 0.0 ? std::min(1.0, std::max(0.0, done / total)) : 1.0);
}

}  // namespace volren
