#include "Commands.h"
#include "ImageWriter.h"
#include "SceneSetup.h"

#include <volume_gui/ChannelPanel.h>
#include <volume_gui/ImGuiOverlay.h>
#include <volume_gui/InteractionQuality.h>
#include <volume_gui/LightDrag.h>
#include <volume_gui/RenderSettingsPanel.h>
#include <volume_gui/TimePlayer.h>
#include <volume_gui/TransferFunctionEditor.h>
#include <volume_renderer/ShaderFunctionRegistry.h>
#include <volume_renderer/VolumeScene.h>

#include <volume_model/DefaultScene.h>

#include <imgui.h>
#include <osg/DisplaySettings>
#include <osgGA/TrackballManipulator>
#include <osgViewer/Viewer>
#include <osgViewer/ViewerEventHandlers>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <iostream>

namespace volren::app {

namespace {

/// 'e' shows and hides the editor (keys ImGui took for a text field do not count).
class EditorToggle : public osgGA::GUIEventHandler
{
public:
    explicit EditorToggle(osg::Node* editor) : _editor(editor) {}
    bool handle(const osgGA::GUIEventAdapter& ea, osgGA::GUIActionAdapter&) override
    {
        if (ea.getHandled() || ea.getEventType() != osgGA::GUIEventAdapter::KEYDOWN || ea.getKey() != 'e') return false;
        _editor->setNodeMask(_editor->getNodeMask() ? 0u : ~0u);
        return true;
    }

private:
    osg::ref_ptr<osg::Node> _editor;
};

/// OSG's trackball, leaving alone the events the editor took.
class Trackball : public osgGA::TrackballManipulator
{
public:
    bool handle(const osgGA::GUIEventAdapter& ea, osgGA::GUIActionAdapter& aa) override
    {
        return !ea.getHandled() && osgGA::TrackballManipulator::handle(ea, aa);
    }
};

/// Reads the window back after the last frame of a --screenshot run.
struct Grab : osg::Camera::DrawCallback
{
    mutable osg::ref_ptr<osg::Image> image = new osg::Image;
    void operator()(osg::RenderInfo& info) const override
    {
        const osg::Viewport* vp = info.getState()->getCurrentViewport();
        image->readPixels(int(vp->x()), int(vp->y()), int(vp->width()), int(vp->height()), GL_RGBA, GL_FLOAT);
    }
};

}  // namespace

namespace {

/// Where the panels go: a column on the left (the transfer-function editor or the channels above,
/// the time player, then the settings), the scene framed in the rest of the window, so that no
/// panel covers the volume or another panel. A window too small for that (--size) gets none: the
/// panels float over the scene in its corners.
struct PanelColumn
{
    int width = 0;  ///< pixels; 0: no column
    float playerY = 400.0f, settingsY = 495.0f;
};

PanelColumn panelColumn(int width, int height)
{
    PanelColumn c;
    if (height >= 960 && width - 660 >= height / 2) c.width = 660;  // the editor's 640 and margins
    return c;
}

/// `regionProjection` (it frames the scene for the window right of the column) as the window's
/// projection: the same pixels per unit, the frame's centre moved into that region.
osg::Matrixd besideColumn(const osg::Matrixd& regionProjection, const PanelColumn& column, int width)
{
    const double share = double(width - column.width) / width;
    return regionProjection * osg::Matrixd::scale(share, 1.0, 1.0) *
           osg::Matrixd::translate(double(column.width) / width, 0.0, 0.0);
}

}  // namespace

int viewCommand(const std::vector<std::string>& args)
{
    RenderOptions options = parseRenderOptions(args, false);
    if (!options.sizeGiven) options.width = 1600, options.height = 960;  // room for the panels beside the scene
    const char* display = std::getenv("DISPLAY");
    if (!display || !*display)
        throw std::runtime_error("volren view needs a display and DISPLAY is not set; use 'volren render' for images");

    osg::ref_ptr<VolumeScene> root = loadScene(options);
    // Interactive views sample far volumes coarser (and keep the mip chain the interaction
    // quality's coarser level needs), unless --set says otherwise.
    auto isSet = [&options](const std::string& name) {
        return std::any_of(options.settings.begin(), options.settings.end(), [&name](const auto& kv) {
            std::string key = kv.first;  // setting keys are case-insensitive
            std::transform(key.begin(), key.end(), key.begin(), [](unsigned char c) { return char(std::tolower(c)); });
            return key == name;
        });
    };
    if (!isSet("lodbydistance"))
        for (VolumeNode* n : findVolumeNodes(*root)) n->settings.lodByDistance = true;
    // Bricked volumes stream in: frames never wait for the loaders, detail arrives over frames.
    if (!isSet("streambricks")) root->pass.streamBricks = true;
    // The scale bar and the axes, unless --no-scale-bar, --no-axes.
    const osg::ref_ptr<Annotations> annotations = addAnnotations(*root, options, true);
    if (options.samples > 1) osg::DisplaySettings::instance()->setNumMultiSamples(options.samples);  // an MSAA window
    osgViewer::Viewer viewer;
    viewer.setThreadingModel(osgViewer::ViewerBase::SingleThreaded);
    viewer.setUseConfigureAffinity(false);  // no pin to CPU 0 for this thread and those it starts
    viewer.setUpViewInWindow(50, 50, options.width, options.height);
    viewer.setSceneData(root.get());

    // The transfer-function editor of the first volume, drawn over the scene.
    const std::vector<VolumeNode*> nodes = findVolumeNodes(*root);
    VolumeNode* node = nodes.empty() ? nullptr : nodes.front();
    const bool panels = node && node->getTransferFunction();
    const PanelColumn column = panels ? panelColumn(options.width, options.height) : PanelColumn{};
    if (annotations) annotations->setLeftMargin(column.width);  // the axes right of the panels
    std::unique_ptr<TransferFunctionEditor> editor;
    std::unique_ptr<ChannelPanel> channels;  // a multi-channel volume: its channels, one editor each
    std::unique_ptr<RenderSettingsPanel> panel;
    TimePlayer player(*root);
    TimePrefetcher prefetcher(*root, std::size_t(1) << 30);  // the next time points, up to 1 GiB of copies
    player.setPrefetcher(&prefetcher);
    osg::ref_ptr<ImGuiOverlay> overlay;
    if (panels) {
        if (node->showsChannels())
            channels = std::make_unique<ChannelPanel>(node);
        else
            editor = std::make_unique<TransferFunctionEditor>(const_cast<TransferFunction*>(node->getTransferFunction()),
                                                              node->getVolume());
        std::map<std::string, std::vector<std::string>> choices;
        for (const char* slot :
             {"RayTraversal", "Reconstruction", "Gradient", "Illumination", "Shadowing", "Acceleration", "Weighting"})
            choices[slot] = root->policy().choosable(slot);  // default first
        // The implementations the node was drawn with in the last frame: their parameters are shown.
        auto drawnWith = [scene = root.get(), name = node->getName()] {
            std::map<std::string, std::string> chosen;
            for (const auto& [drawn, program] : scene->programs())
                if (drawn == name)
                    for (const Binding& b : program->bindings) chosen.emplace(b.function->slot, b.function->name);
            return chosen;
        };
        panel = std::make_unique<RenderSettingsPanel>(node, choices, drawnWith);
        overlay = new ImGuiOverlay([&editor, &channels, &panel, &player, column, scene = root.get()] {
            const ImVec2 display = ImGui::GetIO().DisplaySize;
            ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
            if (channels) channels->draw();
            else editor->draw();
            ImGui::SetNextWindowPos(column.width ? ImVec2(10, column.playerY) : ImVec2(10, display.y - 140),
                                    ImGuiCond_FirstUseEver);
            player.draw();  // a time series: slider, play/pause
            ImGui::SetNextWindowPos(column.width ? ImVec2(10, column.settingsY) : ImVec2(display.x - 410, 10),
                                    ImGuiCond_FirstUseEver);
            panel->draw();
            ImGui::SetNextWindowPos(ImVec2(10, ImGui::GetIO().DisplaySize.y - 40), ImGuiCond_Always);
            ImGui::Begin("frame", nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize);
            ImGui::Text("%.1f ms/frame   e: editor  Ctrl+drag: light  c: screenshot  s: stats  Esc: quit",
                        1000.0f / std::max(ImGui::GetIO().Framerate, 1e-3f));
            if (const std::size_t pending = scene->pendingBricks())  // detail streaming in
                ImGui::Text("loading detail: %zu bricks to go", pending);
            ImGui::End();
        });
        root->addChild(overlay->node());
        viewer.addEventHandler(overlay->eventHandler());
        viewer.addEventHandler(new EditorToggle(overlay->node()));
        viewer.addEventHandler(new InteractionQuality(node));
    }
    viewer.addEventHandler(new LightDrag(root.get(), viewer.getCamera()));  // Ctrl + drag turns the lights
    // Home (the space bar) is the framed view volren render would take, not OSG's bounding sphere.
    osg::ref_ptr<Trackball> trackball = new Trackball;
    {
        const CameraView framed =
            frameScene(*root, cameraRequest(options), double(options.width - column.width) / options.height);
        osg::Vec3d eye, ahead, up;
        framed.view.getLookAt(eye, ahead, up, 1.0);
        const osg::Vec3d forward = ahead - eye;  // the trackball turns about the box centre's depth
        const osg::Vec3d centre = eye + forward * std::max((sceneBoundingBox(*root).center() - eye) * forward, 1e-6);
        trackball->setAutoComputeHomePosition(false);
        trackball->setHomePosition(eye, centre, up);
        viewer.getCamera()->setProjectionMatrix(besideColumn(framed.projection, column, options.width));
    }
    viewer.setCameraManipulator(trackball.get());
    viewer.addEventHandler(new osgViewer::StatsHandler);          // 's': frame time
    viewer.addEventHandler(new osgViewer::ScreenCaptureHandler);  // 'c': screenshot
    viewer.getCamera()->setClearColor(osg::Vec4(options.background, 1.0f));
    viewer.realize();
    if (!viewer.isRealized()) throw std::runtime_error("volren view: cannot open a window on display " + std::string(display));
    // OSG's default state (fixed-function matrices and vertex arrays), as in any OSG viewer: the
    // volume proxies feed their own matrix, and polygon models keep their normals and colours.
    if (!options.screenshot.empty()) {  // headless documentation: N frames, the window to a file
        setUpCamera(*viewer.getCamera(), *root, options, double(options.width - column.width) / options.height);
        viewer.getCamera()->setProjectionMatrix(besideColumn(viewer.getCamera()->getProjectionMatrix(), column, options.width));
        viewer.setCameraManipulator(nullptr);
        osg::ref_ptr<Grab> grab = new Grab;
        for (int i = 0; i < std::max(options.frames, 3); ++i) viewer.frame();
        while (root->pendingBricks() > 0) {  // the picture once the bricks have streamed in
            root->waitForBricks(1.0);
            viewer.frame();
        }
        viewer.getCamera()->setFinalDrawCallback(grab.get());
        viewer.frame();
        writeImage(*grab->image, options.screenshot);
        std::cout << "volren view: wrote " << options.screenshot << std::endl;
        return 0;
    }
    std::cout << "volren view: drag to turn, Ctrl+drag to turn the lights, e: transfer-function editor, s: frame times, "
                 "c: screenshot, Esc quits"
              << std::endl;
    return viewer.run();
}

}  // namespace volren::app
