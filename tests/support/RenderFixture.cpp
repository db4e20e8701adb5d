#include "RenderFixture.h"
#include "TestData.h"

#include <volume_renderer/MatrixUniforms.h>

#include <osg/Geode>
#include <osg/ShapeDrawable>
#include <osg/Geometry>

#include <algorithm>
#include <memory>

namespace volren::test {

namespace {
std::unique_ptr<OffscreenRenderer> shared;
}

OffscreenRenderer& RenderFixture::renderer(int width, int height, int samples)
{
    if (!shared || shared->width() != width || shared->height() != height ||
        (samples > 0 && shared->samples() != samples)) {
        shared.reset();
        shared = std::make_unique<OffscreenRenderer>(width, height, std::max(samples, 1));
    }
    return *shared;
}

Pixels RenderFixture::render(osg::Node* scene, int width, int height, const osg::Matrixd& view,
                             const osg::Matrixd& projection, const osg::Vec3& background)
{
    OffscreenRenderer& r = renderer(width, height);
    r.setScene(scene);
    r.setBackground(background);
    r.camera()->setComputeNearFarMode(osg::CullSettings::DO_NOT_COMPUTE_NEAR_FAR);
    r.camera()->setViewMatrix(view);
    r.camera()->setProjectionMatrix(projection);
    const FrameTiming timing = r.renderFrame();
    for (const std::string& e : timing.glErrors) ADD_FAILURE() << "GL error: " << e;
    Pixels p;
    p.width = width;
    p.height = height;
    const auto* data = reinterpret_cast<const osg::Vec4*>(r.image()->data());
    p.rgba.assign(data, data + std::size_t(width) * height);
    if (const osg::Image* depth = r.depthImage()) {
        const auto* d = reinterpret_cast<const float*>(depth->data());
        p.depth.assign(d, d + std::size_t(width) * height);
    }
    return p;
}

Pixels RenderFixture::renderOrthoFromPlusZ(osg::Node* scene, int width, int height, double viewHeight,
                                           const osg::Vec3& background)
{
    const double h = viewHeight * 0.5, w = h * double(width) / height;
    const double distance = 10.0 * (scene->getBound().radius() + 1.0);
    const osg::Matrixd view = osg::Matrixd::lookAt(osg::Vec3d(0, 0, distance), osg::Vec3d(0, 0, 0), osg::Vec3d(0, 1, 0));
    const osg::Matrixd projection = osg::Matrixd::ortho(-w, w, -h, h, 1.0, 2.0 * distance);
    return render(scene, width, height, view, projection, background);
}

namespace {

/// Draws `geometry` in one flat colour with a GLSL program, the same in compatibility and core
/// profiles (vertex from attribute 0; MatrixUniforms feeds the matrix where OSG does not).
osg::ref_ptr<osg::Node> flatColoured(osg::Geometry* geometry, const osg::Vec4& colour)
{
    geometry->setUseDisplayList(false);
    geometry->setUseVertexBufferObjects(true);
    geometry->setUseVertexArrayObject(true);
    geometry->setDrawCallback(new MatrixUniforms);
    osg::ref_ptr<osg::Program> program = new osg::Program;
    program->addShader(new osg::Shader(osg::Shader::VERTEX, "#version 430 core\n"
                                                            "layout(location = 0) in vec4 osg_Vertex;\n"
                                                            "uniform mat4 osg_ModelViewProjectionMatrix;\n"
                                                            "void main() { gl_Position = osg_ModelViewProjectionMatrix * osg_Vertex; }\n"));
    program->addShader(new osg::Shader(osg::Shader::FRAGMENT, "#version 430 core\n"
                                                              "uniform vec4 colour;\n"
                                                              "out vec4 fragColour;\n"
                                                              "void main() { fragColour = colour; }\n"));
    program->addBindFragDataLocation("fragColour", 0);
    osg::StateSet* ss = geometry->getOrCreateStateSet();
    ss->setAttributeAndModes(program.get(), osg::StateAttribute::ON);
    ss->addUniform(new osg::Uniform("colour", colour));
    ss->setMode(GL_CULL_FACE, osg::StateAttribute::OFF);
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->addDrawable(geometry);
    return geode;
}

}  // namespace

osg::ref_ptr<osg::Node> RenderFixture::flatSquare(const osg::Vec3& centre, float halfSize, const osg::Vec4& colour)
{
    osg::ref_ptr<osg::Vec3Array> corners = new osg::Vec3Array;
    for (const osg::Vec2 c : {osg::Vec2(-1, -1), osg::Vec2(1, -1), osg::Vec2(1, 1), osg::Vec2(-1, 1)})
        corners->push_back(centre + osg::Vec3(c.x(), c.y(), 0.0f) * halfSize);
    osg::ref_ptr<osg::Geometry> square = new osg::Geometry;
    square->setVertexArray(corners.get());
    square->addPrimitiveSet(new osg::DrawArrays(GL_TRIANGLE_FAN, 0, 4));
    return flatColoured(square.get(), colour);
}

osg::ref_ptr<osg::Node> RenderFixture::flatSphere(const osg::Vec3& centre, float radius, const osg::Vec4& colour)
{
    osg::ref_ptr<osg::TessellationHints> hints = new osg::TessellationHints;
    hints->setDetailRatio(12.0f);  // fine: the facets stay within 1e-3 of the true sphere
    osg::ref_ptr<osg::ShapeDrawable> sphere = new osg::ShapeDrawable(new osg::Sphere(centre, radius), hints.get());
    return flatColoured(sphere.get(), colour);
}

osg::ref_ptr<VolumeNode> RenderFixture::volumeNode(Volume* volume, TransferFunction* tf, bool jitter)
{
    return makeVolumeNode(volume, tf, jitter);
}

}  // namespace volren::test
