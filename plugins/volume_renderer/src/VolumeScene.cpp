#include <volume_renderer/MatrixUniforms.h>

#include <volume_renderer/Slots.h>
#include <volume_renderer/VolumeScene.h>
#include <volume_renderer/VolumeTextures.h>

#include <volume_model/ClipMaskNode.h>
#include <volume_model/ClipPlaneNode.h>

#include <osg/BlendFunc>
#include <osg/CullFace>
#include <osg/Depth>
#include <osg/Geode>
#include <osg/Geometry>
#include <osg/LightSource>
#include <osg/Notify>
#include <osgUtil/CullVisitor>

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace volren {

struct VolumeScene::VolumeGL
{
    osg::ref_ptr<const Volume> volume;  // keeps the voxels the texture image points at alive
    osg::ref_ptr<osg::Texture3D> texture;
    unsigned int modified = 0;
    unsigned int lastCull = 0;
};

struct VolumeScene::TableGL
{
    osg::ref_ptr<const TransferFunction> transfer;
    osg::ref_ptr<osg::Texture1D> texture;
    unsigned int modified = 0;
    unsigned int lastCull = 0;
};

struct VolumeScene::Proxy
{
    osg::ref_ptr<osg::MatrixTransform> transform = new osg::MatrixTransform;
    osg::ref_ptr<osg::Geometry> geometry;
    std::string key;
    std::shared_ptr<const ComposedProgram> program;
    osg::Vec3d boxSize;
    unsigned int lastCull = 0;
};

struct VolumeScene::Candidate
{
    VolumeNode* node;
    osg::Matrix matrix;         ///< node -> VolumeScene
    SceneOffer offer;           ///< what the scene offers it
    Composition composition;    ///< its own composition
    osg::BoundingBoxd bound;    ///< its box in the VolumeScene's axes
};

namespace {

/// Groups of candidates whose boxes' bounds overlap (transitively), each in scene order.
template <typename C>
std::vector<std::vector<const C*>> overlapGroups(const std::vector<C>& candidates)
{
    std::vector<std::size_t> group(candidates.size());
    for (std::size_t i = 0; i < group.size(); ++i) group[i] = i;
    auto root = [&](std::size_t i) {
        while (group[i] != i) i = group[i] = group[group[i]];
        return i;
    };
    auto overlap = [](const osg::BoundingBoxd& a, const osg::BoundingBoxd& b) {
        for (int axis = 0; axis < 3; ++axis)
            if (!(a._min[axis] < b._max[axis] && b._min[axis] < a._max[axis])) return false;
        return true;
    };
    for (std::size_t i = 0; i < candidates.size(); ++i)
        for (std::size_t j = i + 1; j < candidates.size(); ++j)
            if (overlap(candidates[i].bound, candidates[j].bound)) group[root(j)] = root(i);
    std::vector<std::vector<const C*>> out;
    std::map<std::size_t, std::size_t> index;
    for (std::size_t i = 0; i < candidates.size(); ++i) {
        auto [it, added] = index.emplace(root(i), out.size());
        if (added) out.emplace_back();
        out[it->second].push_back(&candidates[i]);
    }
    return out;
}

/// Finds volumes, lights and clip shapes below a VolumeScene, with matrices relative to it.
class SceneCollector : public osg::NodeVisitor
{
public:
    explicit SceneCollector(unsigned int mask) : osg::NodeVisitor(TRAVERSE_ACTIVE_CHILDREN) { setTraversalMask(mask); }
    std::vector<std::pair<VolumeNode*, osg::Matrix>> volumes;
    std::vector<std::pair<const osg::LightSource*, osg::Matrix>> lights;
    std::vector<std::pair<const ClipNode*, osg::Matrix>> clips;
    bool opaqueGeometry = false;  ///< some drawable outside the transparent bins

    void apply(osg::Drawable& drawable) override
    {
        if (_transparent == 0 && !isTransparent(drawable.getStateSet())) opaqueGeometry = true;
    }
    void apply(osg::Node& node) override
    {
        const bool transparent = isTransparent(node.getStateSet());
        _transparent += transparent;
        visit(node);
        _transparent -= transparent;
    }
    void apply(osg::LightSource& light) override
    {
        if (light.getLight()) lights.emplace_back(&light, _matrix);
        apply(static_cast<osg::Node&>(light));
    }
    void apply(osg::Transform& transform) override
    {
        const osg::Matrix saved = _matrix;
        transform.computeLocalToWorldMatrix(_matrix, this);
        apply(static_cast<osg::Node&>(transform));
        _matrix = saved;
    }

private:
    /// Whether state puts what it applies to after the opaque bin (blended geometry).
    static bool isTransparent(const osg::StateSet* ss)
    {
        return ss && (ss->getRenderingHint() == osg::StateSet::TRANSPARENT_BIN ||
                      (ss->getRenderBinMode() != osg::StateSet::INHERIT_RENDERBIN_DETAILS && ss->getBinNumber() > 0));
    }
    void visit(osg::Node& node)
    {
        if (auto* v = dynamic_cast<VolumeNode*>(&node)) {
            if (v->getVolume() && v->getTransferFunction() && v->getVolume()->voxelCount() > 0)
                volumes.emplace_back(v, _matrix);
            return;
        }
        if (auto* c = dynamic_cast<ClipNode*>(&node)) {
            clips.emplace_back(c, _matrix);
            return;
        }
        traverse(node);
    }
    osg::Matrix _matrix;
    int _transparent = 0;
};

osg::ref_ptr<osg::Geometry> makeBoxGeometry(const osg::Vec3d& size)
{
    const osg::Vec3 h = osg::Vec3(size) * 0.5f;
    osg::ref_ptr<osg::Vec3Array> corners = new osg::Vec3Array;
    for (int i = 0; i < 8; ++i)
        corners->push_back(osg::Vec3((i & 1) ? h.x() : -h.x(), (i & 2) ? h.y() : -h.y(), (i & 4) ? h.z() : -h.z()));
    // Two counter-clockwise (outward) triangles per face.
    static const GLushort faces[] = {0, 2, 3, 0, 3, 1,  4, 5, 7, 4, 7, 6,  0, 1, 5, 0, 5, 4,
                                     2, 6, 7, 2, 7, 3,  0, 4, 6, 0, 6, 2,  1, 3, 7, 1, 7, 5};
    osg::ref_ptr<osg::Geometry> geometry = new osg::Geometry;
    geometry->setName("volren volume proxy");
    geometry->setUseDisplayList(false);
    geometry->setUseVertexBufferObjects(false);  // buffer objects and a VAO only in core profiles (traverse)
    geometry->setVertexArray(corners.get());
    geometry->addPrimitiveSet(new osg::DrawElementsUShort(GL_TRIANGLES, 36, faces));
    geometry->setDrawCallback(new MatrixUniforms);  // for viewers whose State sets no osg_ matrices
    return geometry;
}

/// Volume texture space -> the VolumeNode's local coordinates.
osg::Matrixd textureToLocal(const Volume& volume)
{
    const osg::Vec3d size = volume.worldSize();
    return osg::Matrixd::translate(-0.5, -0.5, -0.5) * osg::Matrixd::scale(size);
}

/// What the scene offers `volumeMatrix`'s volume (all matrices relative to the VolumeScene).
SceneOffer offerFor(const VolumeNode& node, const osg::Matrix& volumeMatrix, const SceneCollector& scene,
                    const osg::Matrix& sceneModelView)
{
    SceneOffer offer;
    offer.opaqueGeometry = scene.opaqueGeometry;
    const osg::Matrixd sceneToLocal = osg::Matrixd::inverse(volumeMatrix);
    const osg::Matrixd eyeToLocal = osg::Matrixd::inverse(volumeMatrix * sceneModelView);
    for (const auto& [source, matrix] : scene.lights) {
        const osg::Light* light = source->getLight();
        const osg::Vec4d p = light->getPosition();
        const osg::Matrixd toLocal =
            source->getReferenceFrame() == osg::LightSource::ABSOLUTE_RF ? eyeToLocal : matrix * sceneToLocal;
        LightInfo info;
        if (p.w() == 0.0) {
            osg::Vec3d d = osg::Matrixd::transform3x3(osg::Vec3d(p.x(), p.y(), p.z()), toLocal);
            d.normalize();
            info.position = osg::Vec4d(d, 0.0);
        } else {
            info.position = osg::Vec4d(osg::Vec3d(p.x(), p.y(), p.z()) / p.w() * toLocal, 1.0);
        }
        const osg::Vec4 c = light->getDiffuse();
        info.colour = osg::Vec3d(c.r(), c.g(), c.b());
        offer.lights.push_back(info);
    }
    const Volume& volume = *node.getVolume();
    const osg::Matrixd texToScene = textureToLocal(volume) * volumeMatrix;
    for (const auto& [clip, matrix] : scene.clips) {
        const osg::Matrixd texToShape = texToScene * osg::Matrixd::inverse(matrix);
        std::array<osg::Vec3d, 8> corners;
        for (int i = 0; i < 8; ++i) corners[i] = osg::Vec3d(i & 1, (i >> 1) & 1, (i >> 2) & 1) * texToShape;
        if (clip->leavesUnchanged(corners)) continue;
        const ClipInfo info{clip, texToShape};
        if (dynamic_cast<const ClipPlaneNode*>(clip)) offer.planes.push_back(info);
        else offer.shapes.push_back(info);
    }
    return offer;
}

}  // namespace

VolumeScene::VolumeScene() = default;

VolumeScene::VolumeScene(const VolumeScene& other, const osg::CopyOp& copyop)
    : osg::Group(other, copyop), lighting(other.lighting), forceNull(other.forceNull)
{
}

VolumeScene::~VolumeScene() = default;

std::vector<std::pair<std::string, std::string>> VolumeScene::keys()
{
    return {{"lighting", "on/off: off ignores the scene's lights, so the lighting slots become null"},
            {"forceNullAll", "comma-separated slots forced to null for every volume"}};
}

std::string VolumeScene::get(const std::string& key) const
{
    if (key == "lighting") return lighting ? "on" : "off";
    if (key == "forceNullAll") {
        std::string list;
        for (const auto& s : forceNull) list += (list.empty() ? "" : ",") + s;
        return list;
    }
    return {};
}

bool VolumeScene::set(const std::string& key, const std::string& value, std::string& error)
{
    if (key == "lighting") {
        if (value == "on" || value == "1" || value == "true") return lighting = true, true;
        if (value == "off" || value == "0" || value == "false") return lighting = false, true;
        return error = "lighting must be on or off, got '" + value + "'", false;
    }
    if (key == "forceNullAll") {
        RenderSettings probe;  // same slot list and validation as the per-node key
        if (!probe.set("forceNull", value, error)) return false;
        forceNull = probe.forceNull;
        return true;
    }
    error = "'" + key + "' is not a pass setting";
    return false;
}

Composition VolumeScene::chooseComposition(const VolumeNode& node, const SceneOffer& offer) const
{
    const RenderSettings& s = node.settings;
    auto forcedNull = [&](const std::string& slot) { return s.forceNull.count(slot) || forceNull.count(slot); };
    auto chosen = [&](const std::string& slot, const std::string& fallback) -> std::string {
        if (forcedNull(slot)) return "null";
        auto it = s.functions.find(slot);
        return it == s.functions.end() ? fallback : it->second;
    };
    Composition c;
    const std::string setup = chosen("RaySetup", "box_intersection");
    if (setup == "null" || chosen("RayTraversal", "dvr_front_to_back") == "null") {
        // Nothing is marched, so nothing else can run: every other slot is null.
        for (const SlotInfo& slot : slots())
            if (!slot.isTemplate) c.choice[slot.name] = "null";
        c.choice["RaySetup"] = setup;
        return c;
    }
    const std::string traversal = chosen("RayTraversal", "dvr_front_to_back");
    const ShaderFunction* marcher = _compositor.registry().find("RayTraversal", traversal);
    const bool shades = !marcher || marcher->mayCall("Shading");
    const unsigned int lights =
        lighting && shades ? unsigned(std::min<std::size_t>(offer.lights.size(), maxLights)) : 0;
    const std::string illumination = shades ? chosen("Illumination", lights > 0 ? "blinn_phong" : "null") : "null";
    const std::string shading =
        shades ? chosen("Shading", lights > 0 && illumination != "null" ? "lighting" : "null") : "null";
    const bool needGradient = shading != "null" || (marcher && marcher->declaresCall("Gradient"));
    const std::string gradient = chosen("Gradient", needGradient ? "central" : "null");
    c.choice["Illumination"] = illumination;
    c.choice["Shading"] = shading;
    c.choice["RayTraversal"] = traversal;
    c.choice["Gradient"] = gradient;
    c.choice["GradientInput"] = chosen("GradientInput", gradient != "null" ? "scalar" : "null");
    for (const char* slot : {"RaySetup", "Reconstruction", "Classification", "Jitter", "Shadowing", "Acceleration"})
        c.choice[slot] = chosen(slot, findSlot(slot)->defaultFunction);
    c.lightCount = shading == "null" || illumination == "null" ? 0 : lights;
    if (shading == "debug") c.lightCount = lights;

    // Clip planes shorten rays (exact, cheap) unless ray clipping is off; then they clip samples.
    auto rayChoice = s.functions.find("ClipRay");
    auto positionChoice = s.functions.find("ClipPosition");
    const bool planesPerSample = forcedNull("ClipRay") || (rayChoice != s.functions.end() && rayChoice->second == "null") ||
                                 (positionChoice != s.functions.end() && positionChoice->second == "plane");
    const bool positionOff = forcedNull("ClipPosition") ||
                             (positionChoice != s.functions.end() && positionChoice->second == "null");
    std::vector<std::string>& rayInstances = c.instances["ClipRay"];
    std::vector<std::string>& positionInstances = c.instances["ClipPosition"];
    for (std::size_t i = 0; i < offer.planes.size(); ++i) {
        if (!planesPerSample) rayInstances.push_back("plane");
        else if (!positionOff) positionInstances.push_back("plane");
    }
    // Opaque geometry ends the rays where it stands (drawn first; its depth copied for the rays).
    const bool rayClipOff = forcedNull("ClipRay") || (rayChoice != s.functions.end() && rayChoice->second == "null");
    if (offer.opaqueGeometry && !rayClipOff) rayInstances.push_back("depth");
    if (!positionOff)
        for (const ClipInfo& shape : offer.shapes) {
            const char* kind = dynamic_cast<const ClipMaskNode*>(shape.node) ? "mask"
                             : shape.node->className() == std::string("ClipBoxNode") ? "box"
                                                                                    : "ellipsoid";
            positionInstances.push_back(kind);
        }
    return c;
}

double VolumeScene::effectiveSampleDistance(const VolumeNode& node)
{
    const Volume& volume = *node.getVolume();
    const RenderSettings& s = node.settings;
    double step = s.sampleDistance > 0.0 ? s.sampleDistance : s.sampleDistanceFactor * volume.minSpacing();
    const double diagonal = volume.worldSize().length();
    if (!(step > 0.0) || diagonal / step > maxSteps) {
        const double coarser = diagonal / maxSteps;
        OSG_WARN << "volren: sample distance " << step << " would take more than " << maxSteps
                 << " samples per ray; using " << coarser << std::endl;
        step = coarser;
    }
    return step;
}

std::vector<std::string> VolumeScene::compositionKeys() const
{
    std::lock_guard<std::mutex> lock(_mutex);
    return _lastKeys;
}

std::vector<std::pair<std::string, std::shared_ptr<const ComposedProgram>>> VolumeScene::programs() const
{
    std::lock_guard<std::mutex> lock(_mutex);
    std::vector<std::pair<std::string, std::shared_ptr<const ComposedProgram>>> out;
    for (const auto& [node, proxy] : _proxies)
        if (proxy.lastCull == _cullCount && proxy.program) out.emplace_back(node->getName(), proxy.program);
    for (const auto& [nodes, proxy] : _sets) {
        if (proxy.lastCull != _cullCount || !proxy.program) continue;
        std::string names;
        for (const VolumeNode* node : nodes) names += (names.empty() ? "" : " + ") + node->getName();
        out.emplace_back(names, proxy.program);
    }
    return out;
}

std::size_t VolumeScene::auxiliaryTextureCount() const
{
    std::lock_guard<std::mutex> lock(_mutex);
    return _volumeTextures.size() + _tables.size() + _screen.textureCount();
}

std::size_t VolumeScene::textureBytes() const
{
    std::lock_guard<std::mutex> lock(_mutex);
    std::size_t bytes = _screen.textureBytes();
    for (const auto& [key, gl] : _volumeTextures)
        if (const osg::Image* image = gl.texture->getImage()) bytes += image->getTotalSizeInBytes();
    for (const auto& [key, gl] : _tables)
        if (const osg::Image* image = gl.texture->getImage()) bytes += image->getTotalSizeInBytes();
    return bytes;
}

osg::Texture* VolumeScene::volumeTexture(const Volume& volume, bool nearest)
{
    VolumeGL& gl = _volumeTextures[{&volume, nearest}];
    if (!gl.texture || gl.modified != volume.modifiedCount()) {
        gl.volume = &volume;
        gl.texture = makeVolumeTexture(volume);
        if (nearest) {
            gl.texture->setFilter(osg::Texture::MIN_FILTER, osg::Texture::NEAREST);
            gl.texture->setFilter(osg::Texture::MAG_FILTER, osg::Texture::NEAREST);
        }
        gl.modified = volume.modifiedCount();
    }
    gl.lastCull = _cullCount;
    return gl.texture.get();
}

VolumeScene::Proxy& VolumeScene::proxyGeometry(Proxy& proxy, const osg::Vec3d& boxSize, const ComposedProgram& program)
{
    if (!proxy.geometry || proxy.boxSize != boxSize) {
        proxy.boxSize = boxSize;
        proxy.geometry = makeBoxGeometry(proxy.boxSize);
        osg::ref_ptr<osg::Geode> geode = new osg::Geode;
        geode->addDrawable(proxy.geometry.get());
        proxy.transform->removeChildren(0, proxy.transform->getNumChildren());
        proxy.transform->addChild(geode.get());
        proxy.geometry->getOrCreateStateSet();
        proxy.key.clear();
    }
    osg::StateSet& ss = *proxy.geometry->getStateSet();
    if (proxy.key != program.key) {  // new composition: state from scratch
        ss.clear();
        ss.setAttributeAndModes(new osg::CullFace(osg::CullFace::FRONT), osg::StateAttribute::ON);
        ss.setAttributeAndModes(new osg::BlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA), osg::StateAttribute::ON);
        ss.setRenderBinDetails(10, "DepthSortedBin");
        if (program.writesDepth) {  // an opaque surface: depth-tested and written like geometry
            ss.setAttributeAndModes(new osg::Depth(osg::Depth::LESS, 0.0, 1.0, true), osg::StateAttribute::ON);
        } else {
            ss.setMode(GL_DEPTH_TEST, osg::StateAttribute::OFF);
        }
        ss.setAttributeAndModes(program.program.get(), osg::StateAttribute::ON);
        proxy.key = program.key;
    }
    return proxy;
}

VolumeScene::Proxy& VolumeScene::updateProxy(VolumeNode& node, const SceneOffer& offer, const Composition& composition)
{
    const Volume& volume = *node.getVolume();
    std::shared_ptr<const ComposedProgram> program = _compositor.program(composition);
    Proxy& proxy = proxyGeometry(_proxies[&node], volume.worldSize(), *program);
    proxy.program = program;
    BindContext context{node, volume, *node.getTransferFunction(), node.settings, effectiveSampleDistance(node),
                        *proxy.geometry->getStateSet(), program->textureUnits, {}, offer.lights, {}, "", -1, {},
                        program->writesDepth, [this](const Volume& v, bool nearest) { return volumeTexture(v, nearest); },
                        volume.worldSize(), "", {}};
    bind(context, *program, offer, -1);
    return proxy;
}

bool VolumeScene::canShareRay(const Composition& composition)
{
    const std::string traversal = composition.functionFor("RayTraversal");
    return (traversal == "dvr_front_to_back" || traversal == "dvr_back_to_front") &&
           composition.functionFor("RaySetup") != "null";
}

VolumeScene::Proxy& VolumeScene::updateSetProxy(const std::vector<const Candidate*>& members)
{
    // The set's box: the bound of the members' boxes, axis-aligned in the VolumeScene.
    osg::BoundingBoxd bound;
    for (const Candidate* c : members) bound.expandBy(c->bound);
    const osg::Vec3d size = bound._max - bound._min;
    const osg::Matrixd setTextureToScene =
        osg::Matrixd::translate(-0.5, -0.5, -0.5) * osg::Matrixd::scale(size) * osg::Matrixd::translate(bound.center());

    // The set's own slots: its box, its traversal, the first member's jitter, the depth of opaque
    // geometry; everything a sample needs comes from the members' compositions.
    Composition set;
    for (const SlotInfo& slot : slots())
        if (!slot.isTemplate) set.choice[slot.name] = "null";
    set.choice["RaySetup"] = "box_intersection";
    set.choice["RayTraversal"] = "sum_of_media";
    set.choice["Jitter"] = members.front()->composition.functionFor("Jitter");
    double step = std::numeric_limits<double>::infinity();
    double threshold = 1.0;
    bool depth = false;
    std::vector<const VolumeNode*> nodes;
    for (const Candidate* c : members) {
        Composition m = c->composition;
        m.choice["RaySetup"] = "box_intersection";
        m.choice["Jitter"] = "null";
        m.choice["Acceleration"] = "null";
        std::vector<std::string>& rays = m.instances["ClipRay"];
        const auto d = std::find(rays.begin(), rays.end(), "depth");
        if (d != rays.end()) depth = true, rays.erase(d);
        set.members.push_back(m);
        const osg::Vec3d scale = c->matrix.getScale();  // member-local steps in scene units
        step = std::min(step, effectiveSampleDistance(*c->node) * std::min({scale.x(), scale.y(), scale.z()}));
        threshold = std::min(threshold, c->node->settings.earlyTerminationThreshold);
        nodes.push_back(c->node);
    }
    if (depth) set.instances["ClipRay"] = {"depth"};

    std::shared_ptr<const ComposedProgram> program = _compositor.program(set);
    Proxy& proxy = proxyGeometry(_sets[nodes], size, *program);
    proxy.program = program;
    osg::StateSet& ss = *proxy.geometry->getStateSet();
    auto texture = [this](const Volume& v, bool nearest) { return volumeTexture(v, nearest); };

    const Candidate& first = *members.front();
    RenderSettings setSettings = first.node->settings;
    setSettings.earlyTerminationThreshold = threshold;
    BindContext setContext{*first.node, *first.node->getVolume(), *first.node->getTransferFunction(), setSettings, step,
                           ss, program->textureUnits, {}, {}, {}, "", -1, {}, false, texture, size, "", {}};
    bind(setContext, *program, SceneOffer{}, -1);
    for (std::size_t k = 0; k < members.size(); ++k) {
        const Candidate& c = *members[k];
        const Volume& volume = *c.node->getVolume();
        SceneOffer offer = c.offer;
        offer.opaqueGeometry = false;
        const osg::Matrixd memberTextureToScene = textureToLocal(volume) * c.matrix;
        BindContext context{*c.node, volume, *c.node->getTransferFunction(), c.node->settings,
                            effectiveSampleDistance(*c.node), ss, program->textureUnits, {}, offer.lights, {}, "", -1,
                            {}, false, texture, volume.worldSize(), "_v" + std::to_string(k),
                            setTextureToScene * osg::Matrixd::inverse(memberTextureToScene)};
        bind(context, *program, offer, int(k));
    }
    return proxy;
}

void VolumeScene::bind(BindContext& context, const ComposedProgram& program, const SceneOffer& offer, int member)
{
    std::vector<const Binding*> mine;
    for (const Binding& b : program.bindings)
        if (b.member == member) mine.push_back(&b);
    auto needs = [&](AuxData aux) {
        for (const Binding* b : mine)
            if (std::find(b->function->needs.begin(), b->function->needs.end(), aux) != b->function->needs.end())
                return true;
        return false;
    };

    // Auxiliary data: only what the composition's implementations ask for.
    if (needs(AuxData::VolumeTexture)) context.aux[AuxData::VolumeTexture] = volumeTexture(context.volume, false);
    for (bool premultiplied : {false, true}) {
        if (!needs(premultiplied ? AuxData::PremultipliedTable : AuxData::TransferFunctionTable)) continue;
        TableGL& table = _tables[{&context.transfer, premultiplied}];
        if (!table.texture || table.modified != context.transfer.modifiedCount()) {
            table.transfer = &context.transfer;
            table.texture = makeTransferFunctionTexture(context.transfer, premultiplied);
            table.modified = context.transfer.modifiedCount();
        }
        table.lastCull = _cullCount;
        context.aux[premultiplied ? AuxData::PremultipliedTable : AuxData::TransferFunctionTable] = table.texture;
    }
    for (const Binding* b : mine)
        if (b->instance < 0) context.chosen[b->function->slot] = b->function->name;

    // Template instances, in the order chooseComposition made them: ClipRay's are the planes;
    // ClipPosition's are the planes clipped per sample (when rays are not clipped) and the shapes.
    std::size_t rayCount = 0, positionCount = 0;
    for (const Binding* b : mine) {
        rayCount += b->function->slot == "ClipRay" && b->instance >= 0;
        positionCount += b->function->slot == "ClipPosition" && b->instance >= 0;
    }
    const std::vector<ClipInfo> rayClips = rayCount ? offer.planes : std::vector<ClipInfo>();
    std::vector<ClipInfo> positionClips;
    if (positionCount == offer.planes.size() + offer.shapes.size() && rayCount == 0) positionClips = offer.planes;
    if (positionCount) positionClips.insert(positionClips.end(), offer.shapes.begin(), offer.shapes.end());

    for (const Binding* b : mine) {
        if (!b->function->bind) continue;
        context.suffix = b->suffix;
        context.instance = b->instance;
        context.clips = b->function->slot == "ClipRay" ? rayClips : positionClips;
        b->function->bind(context);
    }
}

void VolumeScene::traverse(osg::NodeVisitor& nv)
{
    osg::Group::traverse(nv);
    auto* cv = nv.asCullVisitor();
    if (!cv) return;

    SceneCollector collector(nv.getTraversalMask());
    for (unsigned int i = 0; i < getNumChildren(); ++i) getChild(i)->accept(collector);
    if (collector.lights.size() > maxLights && lighting)
        OSG_WARN << "volren: " << collector.lights.size() << " lights; volumes use the first " << maxLights << std::endl;
    const osg::Matrix sceneModelView = *cv->getModelViewMatrix();

    // Each volume's offer and composition, and its box's bound in the VolumeScene's axes.
    std::vector<Candidate> candidates;
    for (auto& [node, matrix] : collector.volumes) {
        Candidate c{node, matrix, offerFor(*node, matrix, collector, sceneModelView), {}, {}};
        c.composition = forcedComposition ? *forcedComposition : chooseComposition(*node, c.offer);
        const osg::Matrixd texToScene = textureToLocal(*node->getVolume()) * matrix;
        for (int i = 0; i < 8; ++i) c.bound.expandBy(osg::Vec3d(i & 1, (i >> 1) & 1, (i >> 2) & 1) * texToScene);
        candidates.push_back(std::move(c));
    }

    std::lock_guard<std::mutex> lock(_mutex);
    ++_cullCount;
    _screen.beginCull(*cv, _cullCount);
    std::set<std::string> keys;
    // A core profile needs buffer objects and a vertex array object. A compatibility context
    // gets plain client arrays, as OSG 3.6 mishandles both there: display-list models drawn
    // after a VAO drawable vanish from the next frame on. OSG's attribute aliasing, which a core
    // profile needs, tells the two apart.
    const bool core = cv->getState() && cv->getState()->getUseVertexAttributeAliasing();
    auto draw = [&](Proxy& proxy, const osg::Matrix& matrix, const VolumeNode* node) {
        proxy.lastCull = _cullCount;
        if (proxy.geometry->getUseVertexArrayObject() != core) {
            proxy.geometry->setUseVertexBufferObjects(core);
            proxy.geometry->setUseVertexArrayObject(core);
        }
        proxy.transform->setMatrix(matrix);
        keys.insert(proxy.key);
        // Per-camera screen data of the composition: bound by state pushed around the proxy.
        int pushed = 0;
        if (proxy.program->needs(AuxData::DepthTexture)) {
            cv->pushStateSet(_screen.depthState(*cv, proxy.program->textureUnits.at("volren_depthTexture")));
            ++pushed;
        }
        if (proxy.program->needs(AuxData::EntryPoints)) {
            cv->pushStateSet(_screen.entryState(*cv, node, *proxy.geometry, proxy.boxSize, matrix));
            ++pushed;
        }
        proxy.transform->accept(*cv);
        for (; pushed > 0; --pushed) cv->popStateSet();
    };
    for (const std::vector<const Candidate*>& group : overlapGroups(candidates)) {
        const bool shareRay = group.size() > 1 && !forcedComposition &&
                              std::all_of(group.begin(), group.end(),
                                          [](const Candidate* c) { return canShareRay(c->composition); });
        if (shareRay) {
            try {
                Proxy& proxy = updateSetProxy(group);
                osg::BoundingBox bound;
                for (const Candidate* c : group) bound.expandBy(c->bound);
                draw(proxy, osg::Matrix::translate(bound.center()), nullptr);
                continue;
            } catch (const std::exception& e) {
                OSG_WARN << "volren: cannot draw the overlapping volumes '" << group.front()->node->getName()
                         << "', ... as one set (drawn one by one): " << e.what() << std::endl;
            }
        } else if (group.size() > 1) {
            std::vector<const VolumeNode*> nodes;
            for (const Candidate* c : group) nodes.push_back(c->node);
            if (_warnedOverlaps.insert(nodes).second)
                OSG_WARN << "volren: volume '" << group.front()->node->getName() << "' and " << group.size() - 1
                         << " other(s) overlap but not all composite emission-absorption (or a composition is "
                            "forced); they are drawn one after another, which is exact only where they do not overlap"
                         << std::endl;
        }
        for (const Candidate* c : group) {
            try {
                draw(updateProxy(*c->node, c->offer, c->composition), c->matrix, c->node);
            } catch (const std::exception& e) {
                OSG_WARN << "volren: cannot draw volume '" << c->node->getName() << "': " << e.what() << std::endl;
            }
        }
    }
    _lastKeys.assign(keys.begin(), keys.end());

    // Forget nodes that have left the scene, and GL data no composition used lately.
    auto stale = [this](unsigned int last) { return _cullCount - last > 2; };
    for (auto it = _proxies.begin(); it != _proxies.end();) it = stale(it->second.lastCull) ? _proxies.erase(it) : std::next(it);
    for (auto it = _sets.begin(); it != _sets.end();) it = stale(it->second.lastCull) ? _sets.erase(it) : std::next(it);
    for (auto it = _volumeTextures.begin(); it != _volumeTextures.end();)
        it = stale(it->second.lastCull) ? _volumeTextures.erase(it) : std::next(it);
    for (auto it = _tables.begin(); it != _tables.end();) it = stale(it->second.lastCull) ? _tables.erase(it) : std::next(it);
    _screen.endCull(_cullCount);
}

void VolumeScene::checkPrograms(osg::State& state) const
{
    std::lock_guard<std::mutex> lock(_mutex);
    std::vector<const Proxy*> all;
    for (const auto& entry : _proxies) all.push_back(&entry.second);
    for (const auto& entry : _sets) all.push_back(&entry.second);
    for (const Proxy* p : all) {
        const Proxy& proxy = *p;
        if (!proxy.program) continue;
        const osg::Program* program = proxy.program->program.get();
        osg::Program::PerContextProgram* pcp = program->getPCP(state);
        if (!pcp || pcp->isLinked()) continue;
        std::string log = "volren: shader program for '" + proxy.key + "' failed:\n";
        for (unsigned int i = 0; i < program->getNumShaders(); ++i) {
            std::string shaderLog;
            const osg::Shader* shader = program->getShader(i);
            if (osg::Shader::PerContextShader* pcs = shader->getPCS(state); pcs && pcs->getInfoLog(shaderLog))
                log += shader->getName() + ":\n" + shaderLog;
        }
        std::string linkLog;
        program->getGlProgramInfoLog(state.getContextID(), linkLog);
        log += linkLog;
        throw std::runtime_error(ShaderCompositor::explainLog(log, *proxy.program));
    }
}

}  // namespace volren
