// Several views of one scene in an osgViewer::CompositeViewer (one GL context, two cameras of
// different sizes and projections, culled on the main thread and drawn later on OSG's draw
// thread): each view gets its own depth copy and entry-point textures, so each renders exactly
// what a single-view renderer renders for that camera.
#include "RenderFixture.h"
#include "TestData.h"

#include <volume_renderer/HeadlessContext.h>

#include <osg/Image>
#include <osgViewer/CompositeViewer>
#include <osgViewer/GraphicsWindow>

namespace volren::test {
namespace {

class CompositeViewerTest : public RenderFixture
{
};

/// The headless EGL context as OSG's graphics window, so OSG's draw thread can make it current.
class HeadlessWindow : public osgViewer::GraphicsWindowEmbedded
{
public:
    HeadlessWindow(HeadlessContext& context, int width, int height)
        : osgViewer::GraphicsWindowEmbedded(0, 0, width, height), _context(context)
    {
    }
    bool makeCurrentImplementation() override { return _context.makeCurrent(); }
    bool releaseContextImplementation() override { return _context.release(); }

private:
    HeadlessContext& _context;
};

osg::ref_ptr<VolumeScene> mediumWithSquare(const std::string& raySetup)
{
    osg::ref_ptr<VolumeScene> scene = new VolumeScene;
    osg::ref_ptr<VolumeNode> node = RenderFixture::volumeNode(constantVolume(VoxelType::UInt8, {16, 16, 16}, 100).get(),
                                                              constantTransferFunction(osg::Vec4(0.2f, 0.6f, 1.0f, 0.2f)).get());
    std::string error;
    EXPECT_TRUE(node->settings.set("raysetup", raySetup, error)) << error;
    scene->addChild(node.get());
    scene->addChild(RenderFixture::flatSquare({0, 0, -2.0f}, 5.0f, osg::Vec4(1, 0.5f, 0.25f, 1)).get());
    return scene;
}

struct ViewSpec
{
    int width, height;
    osg::Matrixd view, projection;
};

TEST_F(CompositeViewerTest, EachViewRendersWhatASingleViewRendersForItsCamera)
{
    const std::vector<ViewSpec> specs = {
        {48, 40, osg::Matrixd::lookAt(osg::Vec3d(0, 0, 40), osg::Vec3d(0, 0, 0), osg::Vec3d(0, 1, 0)), osg::Matrixd::ortho(-12, 12, -10, 10, 1, 80)},
        {32, 56, osg::Matrixd::lookAt(osg::Vec3d(14, -9, 22), osg::Vec3d(0, 0, 0), osg::Vec3d(0, 0, 1)), osg::Matrixd::perspective(45, 32.0 / 56.0, 5, 80)},
    };
    for (const std::string raySetup : {"box_intersection", "rasterised"}) {
        SCOPED_TRACE(raySetup);
        // What one view alone gives (the shared single-view renderer).
        std::vector<Pixels> alone;
        for (const ViewSpec& s : specs) alone.push_back(render(mediumWithSquare(raySetup).get(), s.width, s.height, s.view, s.projection));

        HeadlessContext context;
        if (context.coreProfile()) GTEST_SKIP() << "core-profile state setup is OffscreenRenderer's; the views are profile-independent";
        context.release();  // OSG's draw thread takes it
        osg::ref_ptr<HeadlessWindow> window = new HeadlessWindow(context, 64, 64);
        osg::ref_ptr<osgViewer::CompositeViewer> viewer = new osgViewer::CompositeViewer;
        // Both cameras are culled before either is drawn: shared screen textures would break.
        viewer->setThreadingModel(osgViewer::ViewerBase::DrawThreadPerContext);
        osg::ref_ptr<VolumeScene> scene = mediumWithSquare(raySetup);  // one scene, seen by both views
        std::vector<osg::ref_ptr<osg::Image>> images;
        for (const ViewSpec& s : specs) {
            osg::ref_ptr<osgViewer::View> view = new osgViewer::View;
            osg::Camera* camera = view->getCamera();
            camera->setGraphicsContext(window.get());
            camera->setViewport(0, 0, s.width, s.height);
            camera->setRenderTargetImplementation(osg::Camera::FRAME_BUFFER_OBJECT);
            osg::ref_ptr<osg::Image> image = new osg::Image;
            image->allocateImage(s.width, s.height, 1, GL_RGBA, GL_FLOAT);
            image->setInternalTextureFormat(GL_RGBA32F_ARB);
            camera->attach(osg::Camera::COLOR_BUFFER, image.get());
            camera->attach(osg::Camera::DEPTH_BUFFER, GL_DEPTH_COMPONENT24);
            camera->setClearColor(osg::Vec4(0, 0, 0, 0));
            camera->setComputeNearFarMode(osg::CullSettings::DO_NOT_COMPUTE_NEAR_FAR);
            camera->setViewMatrix(s.view);
            camera->setProjectionMatrix(s.projection);
            view->setSceneData(scene.get());
            viewer->addView(view.get());
            images.push_back(image);
        }
        viewer->realize();
        for (int frame = 0; frame < 3; ++frame) viewer->frame();
        viewer->stopThreading();  // waits for the last draw (and its read-back)
        EXPECT_EQ(scene->compositionKeys().size(), 1u);
        for (std::size_t v = 0; v < specs.size(); ++v) {
            const auto* data = reinterpret_cast<const osg::Vec4*>(images[v]->data());
            int differing = 0, covered = 0;
            for (std::size_t i = 0; i < alone[v].rgba.size(); ++i) {
                differing += (data[i] - alone[v].rgba[i]).length() > 1e-5f;
                covered += data[i].a() > 0.1f;
            }
            EXPECT_EQ(differing, 0) << "view " << v << " differs from the same camera rendered alone";
            EXPECT_GT(covered, int(alone[v].rgba.size() / 4)) << "view " << v << " shows the volume";
        }
        context.makeCurrent();
        viewer = nullptr;  // releases its GL objects while the context is current
    }
}

}  // namespace
}  // namespace volren::test
