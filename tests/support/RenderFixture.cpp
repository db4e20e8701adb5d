#include "RenderFixture.h"

#include <memory>

namespace volren::test {

namespace {
std::unique_ptr<OffscreenRenderer> shared;
}

OffscreenRenderer& RenderFixture::renderer(int width, int height)
{
    if (!shared || shared->width() != width || shared->height() != height) {
        shared.reset();
        shared = std::make_unique<OffscreenRenderer>(width, height);
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

osg::ref_ptr<VolumeNode> RenderFixture::volumeNode(Volume* volume, TransferFunction* tf, bool jitter)
{
    osg::ref_ptr<VolumeNode> node = new VolumeNode;
    node->setVolume(volume);
    node->setTransferFunction(tf);
    node->settings.functions["Jitter"] = jitter ? "hash" : "null";
    return node;
}

}  // namespace volren::test
