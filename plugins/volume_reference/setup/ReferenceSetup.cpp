#include <volume_reference/ReferenceSetup.h>

#include <volume_renderer/OffscreenRenderer.h>
#include <volume_renderer/ShaderFunctionRegistry.h>
#include <volume_renderer/VolumeScene.h>

#include <volume_model/DefaultScene.h>

#include <stdexcept>

namespace volren {

namespace {

/// Rasterises `scene` without its volumes for `camera`; fills the options' geometry depth and
/// colour when anything was drawn.
void rasteriseGeometry(VolumeScene& scene, const ReferenceCamera& camera,
                       ReferenceOptions& options)
{
    // The scene's own VolumeNodes (what the reference places may be the channels they are drawn as).
    std::vector<std::pair<osg::Node*, osg::Node::NodeMask>> hidden;
    for (VolumeNode* node : findVolumeNodes(scene)) {
        hidden.emplace_back(node, node->getNodeMask());
        node->setNodeMask(0);
    }
    OffscreenRenderer geometry(camera.width, camera.height);
    geometry.setReadDepth(true);
    geometry.setScene(&scene);
    geometry.setBackground(osg::Vec3(options.background));
    geometry.camera()->setViewMatrix(camera.view);
    geometry.camera()->setProjectionMatrix(camera.projection);
    geometry.camera()->setComputeNearFarMode(osg::CullSettings::DO_NOT_COMPUTE_NEAR_FAR);
    geometry.renderFrame();
    for (auto& [node, mask] : hidden) node->setNodeMask(mask);
    const auto* depth = reinterpret_cast<const float*>(geometry.depthImage()->data());
    const auto* colour = reinterpret_cast<const float*>(geometry.image()->data());
    const std::size_t pixels = std::size_t(camera.width) * std::size_t(camera.height);
    bool any = false;
    for (std::size_t i = 0; i < pixels && !any; ++i) any = depth[i] < 1.0f;
    if (!any) return;
    options.geometryDepth.assign(depth, depth + pixels);
    options.geometryColour.assign(colour, colour + pixels * 4);
}

}  // namespace

void applyChoice(ReferenceScene::Placed& placed, const ChosenComposition& chosen, const CompositionPolicy& policy)
{
    const std::map<std::string, std::string>& choice = chosen.composition.choice;
    placed.choice = choice;
    placed.shadows.reset();
    placed.occlusion = placed.shadowsGeometry = false;
    // How it combines with the volumes it overlaps: the set traversal it would be marched by.
    const ShaderFunction* set = policy.setTraversal({chosen});
    const std::string combines = set ? set->traits.combines : std::string();
    placed.blending = combines == "images"   ? ReferenceScene::Blending::Images
                      : combines == "maxima" ? ReferenceScene::Blending::Maxima
                                             : ReferenceScene::Blending::Media;
    // The model of light the chosen Shadowing computes or approximates, as it declares (a
    // plugin's without a declaration: none), and whether it darkens the opaque geometry.
    if (auto it = choice.find("Shadowing"); it != choice.end()) {
        if (const ReferenceModel* model = ReferenceModelCatalog::instance().find("Shadowing", it->second)) {
            const bool shadows = model->fidelity != ReferenceModel::Fidelity::None &&
                                 (model->model == ReferenceScene::exactShadows ||
                                  model->model == ReferenceScene::exactShadowsAndOcclusion);
            placed.shadows = shadows ? ReferenceScene::Shadows::Exact : ReferenceScene::Shadows::None;
            placed.occlusion = shadows && model->model == ReferenceScene::exactShadowsAndOcclusion;
        }
    }
    for (const auto& [slot, name] : choice)  // an implementation that needs a kind of data that darkens it
        if (const ShaderFunction* f = policy.registry().find(slot, name))
            placed.shadowsGeometry = placed.shadowsGeometry || policy.registry().darkensGeometry(*f);
}

ReferenceScene referenceScene(VolumeScene& scene)
{
    ReferenceScene content = ReferenceScene::collect(scene);
    // The policy's choice for each volume: only the number of lights decides its lighting.
    SceneOffer offer;
    offer.lights.resize(content.lights.size());
    for (auto& placed : content.volumes) {
        const auto& node = static_cast<const VolumeNode&>(*placed.node);
        const ChosenComposition chosen = scene.policy().choose(node.settings, offer, scene.pass);
        applyChoice(placed, chosen, scene.policy());
    }
    return content;
}

ReferenceSetup referenceSetup(VolumeScene& scene, const ReferenceCamera& camera, ReferenceOptions options)
{
    ReferenceSetup setup{referenceScene(scene), options};
    if (setup.scene.volumes.empty()) throw std::runtime_error("the scene shows no volume");
    setup.options.lighting = scene.pass.lighting;
    rasteriseGeometry(scene, camera, setup.options);
    return setup;
}

}  // namespace volren
