#include <volume_renderer/VolumeScene.h>
#include <volume_renderer/VolumeTextures.h>

#include <osg/BlendFunc>
#include <osg/CullFace>
#include <osg/Geode>
#include <osg/Geometry>
#include <osg/Notify>
#include <osgUtil/CullVisitor>

#include <algorithm>
#include <set>
#include <stdexcept>

namespace volren {

struct VolumeScene::VolumeGL
{
    osg::ref_ptr<const Volume> volume;  // keeps the voxels the texture image points at alive
    osg::ref_ptr<osg::Texture3D> texture;
    unsigned int modified = 0;
};

struct VolumeScene::TransferGL
{
    osg::ref_ptr<const TransferFunction> transfer;
    osg::ref_ptr<osg::Texture1D> texture;
    unsigned int modified = 0;
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

namespace {

/// Finds the VolumeNodes below a VolumeScene with their matrices relative to it.
class VolumeCollector : public osg::NodeVisitor
{
public:
    explicit VolumeCollector(unsigned int mask) : osg::NodeVisitor(TRAVERSE_ACTIVE_CHILDREN)
    {
        setTraversalMask(mask);
    }
    std::vector<std::pair<VolumeNode*, osg::Matrix>> found;

    void apply(osg::Node& node) override
    {
        if (auto* v = dynamic_cast<VolumeNode*>(&node)) {
            if (v->getVolume() && v->getTransferFunction() && v->getVolume()->voxelCount() > 0)
                found.emplace_back(v, _matrix);
            return;
        }
        traverse(node);
    }
    void apply(osg::Transform& transform) override
    {
        const osg::Matrix saved = _matrix;
        transform.computeLocalToWorldMatrix(_matrix, this);
        traverse(transform);
        _matrix = saved;
    }

private:
    osg::Matrix _matrix;
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
    geometry->setUseVertexBufferObjects(true);
    geometry->setUseVertexArrayObject(true);  // core profiles draw nothing without a bound VAO
    geometry->setVertexArray(corners.get());
    geometry->addPrimitiveSet(new osg::DrawElementsUShort(GL_TRIANGLES, 36, faces));
    return geometry;
}

}  // namespace

VolumeScene::VolumeScene() = default;

VolumeScene::VolumeScene(const VolumeScene& other, const osg::CopyOp& copyop) : osg::Group(other, copyop) {}

VolumeScene::~VolumeScene() = default;

Composition VolumeScene::chooseComposition(const VolumeNode& node)
{
    Composition c;
    c.choice["Jitter"] = node.settings.jitter ? "hash" : "null";
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

VolumeScene::Proxy& VolumeScene::updateProxy(VolumeNode& node)
{
    const Volume& volume = *node.getVolume();
    const TransferFunction& tf = *node.getTransferFunction();
    Proxy& proxy = _proxies[&node];

    if (!proxy.geometry || proxy.boxSize != volume.worldSize()) {
        proxy.boxSize = volume.worldSize();
        proxy.geometry = makeBoxGeometry(proxy.boxSize);
        osg::ref_ptr<osg::Geode> geode = new osg::Geode;
        geode->addDrawable(proxy.geometry.get());
        proxy.transform->removeChildren(0, proxy.transform->getNumChildren());
        proxy.transform->addChild(geode.get());
        osg::StateSet* ss = proxy.geometry->getOrCreateStateSet();
        ss->setAttributeAndModes(new osg::CullFace(osg::CullFace::FRONT), osg::StateAttribute::ON);
        ss->setAttributeAndModes(new osg::BlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA), osg::StateAttribute::ON);
        ss->setMode(GL_DEPTH_TEST, osg::StateAttribute::OFF);
        ss->setRenderBinDetails(10, "DepthSortedBin");
        proxy.key.clear();
    }

    // Shared GL data: one texture per Volume and per TransferFunction, re-made on change.
    VolumeGL& vgl = _volumeTextures[&volume];
    if (!vgl.texture || vgl.modified != volume.modifiedCount()) {
        vgl.volume = &volume;
        vgl.texture = makeVolumeTexture(volume);
        vgl.modified = volume.modifiedCount();
    }
    TransferGL& tgl = _transferTextures[&tf];
    if (!tgl.texture || tgl.modified != tf.modifiedCount()) {
        tgl.transfer = &tf;
        tgl.texture = makeTransferFunctionTexture(tf);
        tgl.modified = tf.modifiedCount();
    }

    std::shared_ptr<const ComposedProgram> program = _compositor.program(chooseComposition(node));
    osg::StateSet& ss = *proxy.geometry->getStateSet();
    if (proxy.key != program->key) {
        ss.setAttributeAndModes(program->program.get(), osg::StateAttribute::ON);
        proxy.key = program->key;
        proxy.program = program;
    }
    BindContext context{node, volume, tf, node.settings, effectiveSampleDistance(node), ss, program->textureUnits, {}};
    context.aux[AuxData::VolumeTexture] = vgl.texture;
    context.aux[AuxData::TransferFunctionTable] = tgl.texture;
    for (const ShaderFunction* f : program->functions)
        if (f->bind) f->bind(context);
    return proxy;
}

void VolumeScene::traverse(osg::NodeVisitor& nv)
{
    osg::Group::traverse(nv);
    auto* cv = nv.asCullVisitor();
    if (!cv) return;

    VolumeCollector collector(nv.getTraversalMask());
    for (unsigned int i = 0; i < getNumChildren(); ++i) getChild(i)->accept(collector);

    std::lock_guard<std::mutex> lock(_mutex);
    ++_cullCount;
    std::set<std::string> keys;
    for (auto& [node, matrix] : collector.found) {
        Proxy* proxy = nullptr;
        try {
            proxy = &updateProxy(*node);
        } catch (const std::exception& e) {
            OSG_WARN << "volren: cannot draw volume '" << node->getName() << "': " << e.what() << std::endl;
            continue;
        }
        proxy->lastCull = _cullCount;
        proxy->transform->setMatrix(matrix);
        keys.insert(proxy->key);
        proxy->transform->accept(*cv);
    }
    _lastKeys.assign(keys.begin(), keys.end());

    // Forget nodes that have left the scene, and GL data nobody uses any more.
    std::set<const Volume*> usedVolumes;
    std::set<const TransferFunction*> usedTransfers;
    for (auto it = _proxies.begin(); it != _proxies.end();) {
        if (_cullCount - it->second.lastCull > 2) it = _proxies.erase(it);
        else {
            usedVolumes.insert(it->first->getVolume());
            usedTransfers.insert(it->first->getTransferFunction());
            ++it;
        }
    }
    for (auto it = _volumeTextures.begin(); it != _volumeTextures.end();)
        it = usedVolumes.count(it->first) ? std::next(it) : _volumeTextures.erase(it);
    for (auto it = _transferTextures.begin(); it != _transferTextures.end();)
        it = usedTransfers.count(it->first) ? std::next(it) : _transferTextures.erase(it);
}

void VolumeScene::checkPrograms(osg::State& state) const
{
    std::lock_guard<std::mutex> lock(_mutex);
    for (const auto& [node, proxy] : _proxies) {
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
