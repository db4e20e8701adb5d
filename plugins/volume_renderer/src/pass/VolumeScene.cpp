#include "GeometryShadows.h"
#include "LevelOfDetail.h"
#include "MultiVolumeSet.h"
#include "ProgramBinder.h"
#include "SceneAnalysis.h"
#include "TextureBudget.h"

#include "../resources/ShadowedGeometry.h"
#include "../resources/TextureCache.h"
#include "../resources/VolumeProxy.h"

#include <volume_renderer/GraphicsDriver.h>
#include <volume_renderer/SampleDistance.h>
#include <volume_renderer/ScreenPasses.h>
#include <volume_renderer/ShaderFunctionRegistry.h>
#include <volume_renderer/VolumeScene.h>

#include <osg/Notify>
#include <osgUtil/CullVisitor>

#include <algorithm>

namespace volren {

/// What the pass keeps between frames: proxies, textures, per-camera screen passes.
struct VolumeScene::Pass
{
    ScreenPasses screen;
    TextureCache textures;
    GeometryShadowMaps geometryShadows;  ///< the opaque geometry's depth from each light
    ShadowedGeometry shadowedGeometry;   ///< the volumes' light volumes darkening that geometry
    std::map<const VolumeNode*, VolumeProxy> proxies;
    std::map<std::vector<const VolumeNode*>, VolumeProxy> sets;  ///< multi-volume sets, by member
    std::set<std::vector<const VolumeNode*>> warnedOverlaps;
    std::vector<std::string> lastKeys;
    std::vector<std::string> errors;  ///< why volumes of the last cull were not drawn
    unsigned int cull = 0;
    osg::ref_ptr<osg::StateSet> normalizing;  ///< GL_NORMALIZE for the models below (compatibility contexts)

    /// Culls `proxy` placed by `matrix`, with the per-camera screen data its program needs.
    void draw(osgUtil::CullVisitor& cv, VolumeProxy& proxy, const osg::Matrix& matrix, const VolumeNode* node,
              std::set<std::string>& keys);
    /// Composes and binds the proxy of one volume.
    VolumeProxy& update(const VolumeCandidate& c, const ChosenComposition& chosen, ShaderCompositor& compositor);
    /// Schedules the darkening of the opaque geometry by `c`'s built volume of a kind that darkens
    /// it (AuxKind::darkensGeometry) where `composition` (lit) needs one and `proxy` was drawn.
    void shadowGeometry(osgUtil::CullVisitor& cv, const VolumeCandidate& c, const Composition& composition,
                        const VolumeProxy& proxy);
    /// Forgets proxies and textures no cull traversal used lately.
    void endCull();
};

void VolumeScene::Pass::draw(osgUtil::CullVisitor& cv, VolumeProxy& proxy, const osg::Matrix& matrix,
                             const VolumeNode* node, std::set<std::string>& keys)
{
    proxy.lastCull = cull;
    keys.insert(proxy.key);
    if (proxy.hidden) return;  // exactly what drawing it would show: nothing
    // A core profile needs buffer objects and a vertex array object. A compatibility context
    // gets plain client arrays, as OSG 3.6 mishandles both there: display-list models drawn
    // after a VAO drawable vanish from the next frame on. OSG's attribute aliasing, which a core
    // profile needs, tells the two apart.
    proxy.useVertexArrayObject(cv.getState() && cv.getState()->getUseVertexAttributeAliasing());
    proxy.transform->setMatrix(matrix);
    if (!proxy.prepasses.empty()) {  // under the ray caster's uniforms and textures
        cv.pushStateSet(proxy.geometry->getStateSet());
        for (const osg::ref_ptr<osg::Node>& node : proxy.prepasses) node->accept(cv);
        cv.popStateSet();
    }
    // The per-camera auxiliary data its program needs, each kind once.
    std::vector<const AuxKind*> perCamera;
    for (const Binding& b : proxy.program->bindings)
        for (const AuxKind* kind : b.kinds)
            if (kind->scope == AuxScope::Camera && std::find(perCamera.begin(), perCamera.end(), kind) == perCamera.end())
                perCamera.push_back(kind);
    int pushed = 0;
    for (const AuxKind* kind : perCamera) {
        AuxCameraRequest request{.cv = cv, .screen = screen, .program = *proxy.program, .node = node, .box = *proxy.geometry,
                              .boxSize = proxy.boxSize, .matrix = matrix};
        cv.pushStateSet(kind->perCamera(request));
        ++pushed;
    }
    proxy.transform->accept(cv);
    for (; pushed > 0; --pushed) cv.popStateSet();
}

VolumeProxy& VolumeScene::Pass::update(const VolumeCandidate& c, const ChosenComposition& chosen,
                                       ShaderCompositor& compositor)
{
    std::shared_ptr<const ComposedProgram> program = compositor.program(chosen.composition);
    VolumeProxy& proxy = proxies[c.node];
    osg::StateSet& ss = proxy.update(c.node->getVolume()->worldSize(), program);
    BindContext context = bindContextFor(c, ss, *program);
    context.lights = c.offer.lights;
    context.writesDepth = program->writesDepth;
    proxy.hidden = !bindProgram(context, *program, chosen.clips, -1, textures, cull);
    proxy.prepasses = std::move(context.prepasses);
    return proxy;
}

void VolumeScene::Pass::shadowGeometry(osgUtil::CullVisitor& cv, const VolumeCandidate& c,
                                       const Composition& composition, const VolumeProxy& proxy)
{
    // A hidden volume (its TF shows nothing) casts no shadow, and its light volume was not rebuilt.
    if (proxy.hidden || !c.offer.opaqueGeometry || composition.lightCount == 0 || c.offer.lights.empty()) return;
    osg::Texture3D* lightVolume = nullptr;  // each light's transmittance
    for (const auto& [slot, name] : composition.choice)
        if (const ShaderFunction* f = ShaderFunctionRegistry::instance().find(slot, name))
            for (const AuxKind* kind : ShaderFunctionRegistry::instance().auxKindsOf(*f))
                if (kind->darkensGeometry && !lightVolume) lightVolume = textures.builtVolumes().find(c.node, kind->name);
    if (!lightVolume) return;
    const std::vector<LightInfo> lights(c.offer.lights.begin(),
                                        c.offer.lights.begin() + std::min<std::ptrdiff_t>(composition.lightCount,
                                                                                          std::ptrdiff_t(c.offer.lights.size())));
    shadowedGeometry.cull(cv, c.node, c.node->getVolume()->worldSize(), lightVolume, lights, c.matrix,
                          screen.depthState(cv, 0), cull);
}

void VolumeScene::Pass::endCull()
{
    auto stale = [this](unsigned int last) { return cull - last > 2; };
    for (auto it = proxies.begin(); it != proxies.end();) it = stale(it->second.lastCull) ? proxies.erase(it) : std::next(it);
    for (auto it = sets.begin(); it != sets.end();) it = stale(it->second.lastCull) ? sets.erase(it) : std::next(it);
    textures.endCull(cull);
    screen.endCull(cull);
    shadowedGeometry.endCull(cull);
}

VolumeScene::VolumeScene() : _state(std::make_unique<Pass>()) {}

VolumeScene::VolumeScene(const VolumeScene& other, const osg::CopyOp& copyop)
    : osg::Group(other, copyop), pass(other.pass), _state(std::make_unique<Pass>())
{
}

VolumeScene::~VolumeScene() = default;

void VolumeScene::traverse(osg::NodeVisitor& nv)
{
    auto* cv = nv.asCullVisitor();
    // Models placed under a scaling transform keep unit normals, so they are lit as at unit
    // scale (fixed-function lighting of a compatibility context; a core profile has no such
    // mode and its shaders normalise themselves).
    const bool normalize = cv && cv->getState() && !cv->getState()->getUseVertexAttributeAliasing();
    if (normalize) {
        if (!_state->normalizing) {
            _state->normalizing = new osg::StateSet;
            _state->normalizing->setMode(GL_NORMALIZE, osg::StateAttribute::ON);
        }
        cv->pushStateSet(_state->normalizing.get());
    }
    osg::Group::traverse(nv);
    if (normalize) cv->popStateSet();
    if (!cv) return;

    std::vector<VolumeCandidate> candidates =
        analyseScene(*this, nv.getTraversalMask(), *cv->getModelViewMatrix(), pass.lighting);
    const bool coarseBytes = filtersBytesCoarsely();
    for (VolumeCandidate& c : candidates) {
        c.lod = levelOfDetail(c, *cv);
        c.coarseByteFiltering = coarseBytes;
        c.offer.exceedsTextureBudget = exceedsTextureBudget(*c.node, c.lod, coarseBytes);
        c.offer.coarsePreview = c.node->getVolume()->fullResolution() != nullptr;
        c.textureToClip = textureToLocal(*c.node->getVolume()) * c.matrix * *cv->getModelViewMatrix() * *cv->getProjectionMatrix();
    }
    std::vector<ChosenComposition> chosen;
    std::vector<osg::BoundingBoxd> bounds;
    for (const VolumeCandidate& c : candidates) {
        chosen.push_back(forcedComposition ? ChosenComposition{*forcedComposition,
                                                               _policy.assignClips(*forcedComposition, c.offer)}
                                           : _policy.choose(c.node->settings, c.offer, pass));
        bounds.push_back(c.bound);
    }
    std::vector<const Composition*> compositions;
    for (const ChosenComposition& c : chosen) compositions.push_back(&c.composition);

    std::lock_guard<std::mutex> lock(_mutex);
    Pass& p = *_state;
    ++p.cull;
    p.screen.beginCull(*cv, p.cull);
    p.textures.setBrickStreaming(std::size_t(pass.uploadBudgetMB * 1048576.0), !pass.streamBricks);
    cullGeometryShadows(*cv, *this, candidates, chosen, _policy.registry(), p.geometryShadows);
    std::set<std::string> keys;
    p.errors.clear();
    for (const RayGroup& group : _policy.rayGroups(bounds, compositions, forcedComposition.has_value())) {
        std::vector<const VolumeNode*> nodes;
        for (std::size_t i : group.members) nodes.push_back(candidates[i].node);
        if (group.shared) {
            try {
                std::vector<SetMember> members;
                for (std::size_t i : group.members) members.push_back({&candidates[i], chosen[i]});
                VolumeProxy& proxy = p.sets[nodes];
                updateSetProxy(proxy, members, _policy, _compositor, p.textures, p.cull);
                osg::BoundingBox box;  // in float, as the proxy's vertices
                for (const SetMember& m : members) box.expandBy(osg::BoundingBox(m.candidate->bound));
                p.draw(*cv, proxy, osg::Matrix::translate(box.center()), nullptr, keys);
                for (const SetMember& m : members) p.shadowGeometry(*cv, *m.candidate, m.chosen.composition, proxy);
                continue;
            } catch (const std::exception& e) {
                OSG_WARN << "volren: cannot draw the overlapping volumes '" << nodes.front()->getName()
                         << "', ... as one set (drawn one by one): " << e.what() << std::endl;
            }
        } else if (nodes.size() > 1 && p.warnedOverlaps.insert(nodes).second) {
            OSG_WARN << "volren: volume '" << nodes.front()->getName() << "' and " << nodes.size() - 1
                     << " other(s) overlap but are not all drawn by traversals of one kind that share a ray "
                        "(emission-absorption, or MIP), or a composition is forced; they are drawn one after "
                        "another, which is exact only where they do not overlap"
                     << std::endl;
        }
        for (std::size_t i : group.members) {
            try {
                VolumeProxy& proxy = p.update(candidates[i], chosen[i], _compositor);
                p.draw(*cv, proxy, candidates[i].matrix, candidates[i].node, keys);
                p.shadowGeometry(*cv, candidates[i], chosen[i].composition, proxy);
            } catch (const std::exception& e) {
                OSG_WARN << "volren: cannot draw volume '" << candidates[i].node->getName() << "': " << e.what()
                         << std::endl;
                p.errors.push_back("volume '" + candidates[i].node->getName() + "': " + e.what());
            }
        }
    }
    p.lastKeys.assign(keys.begin(), keys.end());
    p.endCull();
}

std::vector<std::string> VolumeScene::compositionKeys() const
{
    std::lock_guard<std::mutex> lock(_mutex);
    return _state->lastKeys;
}

std::vector<std::string> VolumeScene::drawErrors() const
{
    std::lock_guard<std::mutex> lock(_mutex);
    return _state->errors;
}

std::vector<BrickStatistics> VolumeScene::brickStatistics() const
{
    std::lock_guard<std::mutex> lock(_mutex);
    return _state->textures.brickStatistics(_state->cull);
}

std::vector<BuiltVolumeStatistics> VolumeScene::builtVolumeStatistics() const
{
    std::lock_guard<std::mutex> lock(_mutex);
    return _state->textures.builtVolumes().statistics(_state->cull);
}

unsigned int VolumeScene::geometryShadowMapDraws() const
{
    std::lock_guard<std::mutex> lock(_mutex);
    return _state->geometryShadows.draws();
}

std::size_t VolumeScene::pendingBricks() const
{
    std::lock_guard<std::mutex> lock(_mutex);
    return _state->textures.pendingBricks(_state->cull);
}

void VolumeScene::waitForBricks(double seconds) const
{
    std::lock_guard<std::mutex> lock(_mutex);
    _state->textures.waitForBricks(_state->cull, seconds);
}

std::size_t VolumeScene::hiddenVolumeCount() const
{
    std::lock_guard<std::mutex> lock(_mutex);
    std::size_t n = 0;
    for (const auto& entry : _state->proxies) n += entry.second.lastCull == _state->cull && entry.second.hidden;
    for (const auto& entry : _state->sets) n += entry.second.lastCull == _state->cull && entry.second.hidden;
    return n;
}

std::vector<std::pair<std::string, std::shared_ptr<const ComposedProgram>>> VolumeScene::programs() const
{
    std::lock_guard<std::mutex> lock(_mutex);
    std::vector<std::pair<std::string, std::shared_ptr<const ComposedProgram>>> out;
    for (const auto& [node, proxy] : _state->proxies)
        if (proxy.lastCull == _state->cull && proxy.program) out.emplace_back(node->getName(), proxy.program);
    for (const auto& [nodes, proxy] : _state->sets) {
        if (proxy.lastCull != _state->cull || !proxy.program) continue;
        std::string names;
        for (const VolumeNode* node : nodes) names += (names.empty() ? "" : " + ") + node->getName();
        out.emplace_back(names, proxy.program);
    }
    return out;
}

std::size_t VolumeScene::auxiliaryTextureCount() const
{
    std::lock_guard<std::mutex> lock(_mutex);
    return _state->textures.count() + _state->screen.textureCount();
}

std::size_t VolumeScene::textureBytes() const
{
    std::lock_guard<std::mutex> lock(_mutex);
    return _state->screen.textureBytes() + _state->textures.bytes();
}

void VolumeScene::checkPrograms(osg::State& state) const
{
    std::lock_guard<std::mutex> lock(_mutex);
    std::vector<const VolumeProxy*> all;
    for (const auto& entry : _state->proxies) all.push_back(&entry.second);
    for (const auto& entry : _state->sets) all.push_back(&entry.second);
    for (const VolumeProxy* proxy : all) {
        // Only what the last cull drew: another viewer of the same scene (a second context) has
        // not applied the programs of proxies it did not draw.
        if (!proxy->program || proxy->lastCull != _state->cull || proxy->hidden) continue;  // hidden: never applied
        // The ray caster, and the build programs of its auxiliary data where it has them.
        std::vector<std::pair<const osg::Program*, const std::vector<std::string>*>> programs = {
            {proxy->program->program.get(), &proxy->program->sourceNames}};
        for (const auto& [member, build] : proxy->program->builds) programs.emplace_back(build.program.get(), &build.sourceNames);
        for (const auto& [program, names] : programs) {
            osg::Program::PerContextProgram* pcp = program ? program->getPCP(state) : nullptr;
            if (!pcp || pcp->needsLink() || pcp->isLinked()) continue;  // never linked: not applied (culled later)
            std::string log = "volren: shader program " + program->getName() + " for '" + proxy->key + "' failed:\n";
            for (unsigned int i = 0; i < program->getNumShaders(); ++i) {
                std::string shaderLog;
                const osg::Shader* shader = program->getShader(i);
                if (osg::Shader::PerContextShader* pcs = shader->getPCS(state); pcs && pcs->getInfoLog(shaderLog))
                    log += shader->getName() + ":\n" + shaderLog;
            }
            std::string linkLog;
            program->getGlProgramInfoLog(state.getContextID(), linkLog);
            log += linkLog;
            throw std::runtime_error(ShaderCompositor::explainLog(log, *names));
        }
    }
}

}  // namespace volren
