#include "ShadowedGeometry.h"

#include "LightVolume.h"

#include <volume_renderer/MatrixUniforms.h>
#include <volume_renderer/ShaderFunctionRegistry.h>

#include <osg/BlendFunc>
#include <osg/Depth>
#include <osg/Geode>
#include <osg/Geometry>
#include <osg/MatrixTransform>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace volren {

namespace {

/// The bound of a drawable whose vertices are not where it draws: its initial bound alone.
struct InitialBoundOnly : osg::Drawable::ComputeBoundingBoxCallback
{
    osg::BoundingBox computeBound(const osg::Drawable&) const override { return {}; }
};

}  // namespace

struct ShadowedGeometry::Pass
{
    osg::ref_ptr<osg::MatrixTransform> transform = new osg::MatrixTransform;
    osg::ref_ptr<osg::Geometry> triangle = new osg::Geometry;
    unsigned int lastCull = 0;
};

ShadowedGeometry::ShadowedGeometry() = default;
ShadowedGeometry::~ShadowedGeometry() = default;

void ShadowedGeometry::cull(osgUtil::CullVisitor& cv, const void* node, const osg::Vec3d& worldSize,
                            osg::Texture3D* lightVolume, const std::vector<LightInfo>& lights, const osg::Matrix& matrix,
                            osg::StateSet* depthState, unsigned int cullCount)
{
    if (!_program) {
        const ShaderFunctionRegistry& registry = ShaderFunctionRegistry::instance();
        _program = new osg::Program;
        _program->setName("volren shadowed geometry");
        _program->addShader(new osg::Shader(osg::Shader::VERTEX, registry.read("Shadowing/shadowed_geometry.vert")));
        // The light volume's layered read, shared with Shadowing/light_volume, after the declarations.
        std::string fragment = registry.read("Shadowing/shadowed_geometry.frag");
        const std::string mark = "out vec4 volren_fragColour;\n";
        const std::size_t at = fragment.find(mark);
        if (at == std::string::npos)
            throw std::runtime_error("Shadowing/shadowed_geometry.frag: no '" + mark.substr(0, mark.size() - 1) +
                                     "' to put Shadowing/light_volume_layers.glsl after");
        fragment.insert(at + mark.size(), registry.read("Shadowing/light_volume_layers.glsl"));
        _program->addShader(new osg::Shader(osg::Shader::FRAGMENT, fragment));
        _program->addBindFragDataLocation("volren_fragColour", 0);
    }
    Pass& pass = _passes[{cv.getCurrentCamera(), node}];
    osg::Geometry& triangle = *pass.triangle;
    if (!triangle.getVertexArray()) {
        osg::ref_ptr<osg::Vec3Array> corners = new osg::Vec3Array;  // NDC: covers the viewport
        for (const osg::Vec3 c : {osg::Vec3(-1, -1, 0), osg::Vec3(3, -1, 0), osg::Vec3(-1, 3, 0)}) corners->push_back(c);
        triangle.setName("volren shadowed geometry");
        triangle.setVertexArray(corners.get());
        triangle.addPrimitiveSet(new osg::DrawArrays(GL_TRIANGLES, 0, 3));
        triangle.setUseDisplayList(false);
        triangle.setDrawCallback(new MatrixUniforms);
        triangle.setComputeBoundingBoxCallback(new InitialBoundOnly);
        triangle.setCullingActive(false);  // drawn wherever the volume is: its shadow may be in view when it is not
        osg::StateSet* ss = triangle.getOrCreateStateSet();
        ss->setAttributeAndModes(_program.get(), osg::StateAttribute::ON);
        // colour *= the fragment's colour; alpha (coverage) kept.
        ss->setAttributeAndModes(new osg::BlendFunc(GL_ZERO, GL_SRC_COLOR, GL_ZERO, GL_ONE), osg::StateAttribute::ON);
        ss->setAttributeAndModes(new osg::Depth(osg::Depth::ALWAYS, 0.0, 1.0, false), osg::StateAttribute::ON);
        ss->setMode(GL_DEPTH_TEST, osg::StateAttribute::OFF);
        ss->setMode(GL_CULL_FACE, osg::StateAttribute::OFF);
        ss->addUniform(new osg::Uniform("volren_lightVolume", 1));
        ss->setRenderBinDetails(7, "RenderBin");
        osg::ref_ptr<osg::Geode> geode = new osg::Geode;
        geode->addDrawable(&triangle);
        geode->setCullingActive(false);
        pass.transform->addChild(geode.get());
    }
    // A core profile needs buffer objects and a VAO; a compatibility context draws client
    // arrays (as the volume proxies, see VolumeScene).
    const bool core = cv.getState() && cv.getState()->getUseVertexAttributeAliasing();
    if (triangle.getUseVertexArrayObject() != core) {
        triangle.setUseVertexBufferObjects(core);
        triangle.setUseVertexArrayObject(core);
    }
    // Its near/far share is the volume's box.
    const osg::Vec3 half = osg::Vec3(worldSize) * 0.5f;
    triangle.setInitialBound(osg::BoundingBox(-half, half));
    osg::StateSet* ss = triangle.getStateSet();
    ss->setTextureAttribute(1, lightVolume, osg::StateAttribute::ON);
    ss->getOrCreateUniform("volren_worldSize", osg::Uniform::FLOAT_VEC3)->set(osg::Vec3f(worldSize));
    const int held = int(std::min<std::size_t>(lights.size(), lightVolumeMaxLights));
    ss->getOrCreateUniform("volren_lightLayers", osg::Uniform::INT)->set(lightVolumeLayers(lights.size()));
    ss->getOrCreateUniform("volren_heldLights", osg::Uniform::INT)->set(held);
    ss->getOrCreateUniform("volren_totalLights", osg::Uniform::INT)->set(int(lights.size()));
    osg::Uniform* placed = ss->getOrCreateUniform("volren_textureLights", osg::Uniform::FLOAT_VEC4, lightVolumeMaxLights);
    for (int i = 0; i < held; ++i) {  // in texture space, as the light volume's build places them
        placed->setElement(unsigned(i), osg::Vec4f(lightInTextureSpace(lights[std::size_t(i)], worldSize)));
    }
    pass.lastCull = cullCount;
    pass.transform->setMatrix(matrix);
    cv.pushStateSet(depthState);
    pass.transform->accept(cv);
    cv.popStateSet();
}

void ShadowedGeometry::endCull(unsigned int cullCount)
{
    for (auto it = _passes.begin(); it != _passes.end();)
        it = cullCount - it->second.lastCull > 2 ? _passes.erase(it) : std::next(it);
}

}  // namespace volren
