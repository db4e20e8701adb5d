#include <volume_model/AutoTransferFunction.h>
#include <volume_model/DefaultScene.h>
#include <volume_model/ReadVolume.h>

#include <osg/NodeVisitor>
#include <osg/Notify>
#include <osgDB/ObjectWrapper>
#include <osgDB/Registry>

namespace volren {

osg::ref_ptr<osg::Group> makeSceneRoot()
{
    // The model has no GL, so it does not link the renderer: OSG's wrapper registry creates the
    // pass from its class name, loading osgdb_serializers_volren (which links the renderer).
    registerPluginPath();
    osgDB::ObjectWrapper* wrapper =
        osgDB::Registry::instance()->getObjectWrapperManager()->findWrapper("volren::VolumeScene");
    osg::ref_ptr<osg::Object> made = wrapper ? wrapper->createInstance() : nullptr;
    if (auto* pass = dynamic_cast<osg::Group*>(made.get())) return pass;
    OSG_WARN << "volren: no volren::VolumeScene (plugin osgdb_serializers_volren not on OSG's library path); "
                "the default scene will not render its volume in a stock OSG viewer" << std::endl;
    return new osg::Group;
}

osg::ref_ptr<osg::LightSource> makeHeadlight()
{
    osg::ref_ptr<osg::LightSource> headlight = new osg::LightSource;
    headlight->setName("headlight");
    headlight->setReferenceFrame(osg::LightSource::ABSOLUTE_RF);  // eye coordinates: moves with the camera
    headlight->getLight()->setLightNum(0);
    headlight->getLight()->setPosition(osg::Vec4(0.0f, 0.0f, 1.0f, 0.0f));  // directional, along the view
    return headlight;
}

osg::ref_ptr<VolumeNode> makeDefaultVolumeNode(Volume* volume)
{
    osg::ref_ptr<VolumeNode> node = new VolumeNode;
    node->setName(volume->sourceFile.empty() ? std::string("volume") : volume->sourceFile);
    node->setVolume(volume);
    node->setTransferFunction(makeTransferFunctionFromHistogram(*volume));
    // Several channels (a fluorescence stack): each in its own colour over its own window,
    // emitting unlit (no CT colours, no shading of noise).
    if (volume->channels() > 1 && !volume->fullResolution()) {
        node->channels = defaultChannelDisplays(*volume);
        node->settings.functions["Shading"] = "null";
    }
    return node;
}

osg::ref_ptr<osg::Group> makeDefaultScene(Volume* volume)
{
    osg::ref_ptr<osg::Group> root = makeSceneRoot();
    root->setName("volren default scene");
    root->addChild(makeHeadlight());
    root->addChild(makeDefaultVolumeNode(volume));
    return root;
}

VolumeNode* findFirstVolumeNode(osg::Node* root)
{
    struct Finder : osg::NodeVisitor
    {
        Finder() : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN) {}
        VolumeNode* found = nullptr;
        void apply(osg::Node& node) override
        {
            if (found) return;
            if (auto* v = dynamic_cast<VolumeNode*>(&node)) found = v;
            else traverse(node);
        }
    } finder;
    if (root) root->accept(finder);
    return finder.found;
}

std::vector<VolumeNode*> findVolumeNodes(osg::Node& root)
{
    struct Collect : osg::NodeVisitor
    {
        Collect() : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN) {}
        std::vector<VolumeNode*> nodes;
        void apply(osg::Node& node) override
        {
            if (auto* v = dynamic_cast<VolumeNode*>(&node)) nodes.push_back(v);
            traverse(node);
        }
    } collect;
    root.accept(collect);
    return collect.nodes;
}

}  // namespace volren
