// The transfer-function editor driven headlessly: synthetic ImGui input on an EGL context, one
// rendered frame per input step, the editor drawn by ImGuiOverlay over a real volume.
#include "RenderFixture.h"
#include "TestData.h"

#include <volume_gui/ImGuiOverlay.h>
#include <volume_gui/InteractionQuality.h>
#include <volume_gui/TransferFunctionEditor.h>

#include <volume_model/ReadVolume.h>
#include <volume_model/TransferFunctionFile.h>

#include <imgui.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <sys/stat.h>

namespace volren::test {
namespace {

/// The pixel ImGui puts the mouse on for `p` (it floors mouse positions).
ImVec2 pixelOf(const ImVec2& p)
{
    return ImVec2(std::floor(p.x), std::floor(p.y));
}

/// One frame's input.
struct Input
{
    ImVec2 mouse{-100, -100};
    bool left = false, right = false;
    bool ctrlZ = false;
};

class Editor : public RenderFixture
{
public:
    static constexpr int width = 640, height = 480;

protected:
    void SetUp() override
    {
        tf = new TransferFunction;
        tf->setPoint(0, osg::Vec4(0, 0, 0, 0));
        tf->setPoint(255, osg::Vec4(1, 1, 1, 1));
        tf->setDomain(0, 255);
        volume = constantVolume(VoxelType::UInt8, {16, 16, 16}, 100);
        editor = std::make_unique<TransferFunctionEditor>(tf.get(), volume.get());
        overlay = new ImGuiOverlay([this] {
            ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_Always);
            editor->draw();
        });
        overlay->beforeFrame = [this](ImGuiIO& io) {
            io.MousePos = input.mouse;
            io.MouseDown[0] = input.left;
            io.MouseDown[1] = input.right;
            io.KeyCtrl = input.ctrlZ;
            io.KeysDown['z'] = input.ctrlZ;
        };
        scene = new VolumeScene;
        scene->addChild(volumeNode(volume.get(), tf.get()).get());
        scene->addChild(overlay->node());
        frame();  // lays the editor out: the canvas exists from here on
    }

    /// Renders one frame with `in` as the input.
    Pixels frame(const Input& in = {})
    {
        input = in;
        return renderOrthoFromPlusZ(scene.get(), width, height, 40.0, {0, 0, 0});
    }
    /// Presses, (moves), releases the left button: one finished edit.
    void drag(const ImVec2& from, const ImVec2& to)
    {
        frame({from});
        frame({from, true});
        frame({ImVec2((from.x + to.x) / 2, (from.y + to.y) / 2), true});
        frame({to, true});
        frame({to, false});
    }
    void rightClick(const ImVec2& at)
    {
        frame({at});
        frame({at, false, true});
        frame({at});
    }

    osg::ref_ptr<TransferFunction> tf;
    osg::ref_ptr<Volume> volume;
    std::unique_ptr<TransferFunctionEditor> editor;
    osg::ref_ptr<ImGuiOverlay> overlay;
    osg::ref_ptr<VolumeScene> scene;
    Input input;
};

TEST_F(Editor, AddDragDeleteUndoAndRedoChangeTheModelExactly)
{
    const TransferFunction::Points original = tf->points();
    editor->channel = TransferFunctionEditor::Channel::Alpha;

    // Add: a click on empty canvas puts a point at the value and opacity under the mouse; the
    // colour keeps its curve (the evaluated colour there).
    const ImVec2 at = pixelOf(editor->screenPosition(100.0, 0.5));
    const auto [v1, a1] = editor->valueAt(at);
    const osg::Vec4 before = tf->evaluate(v1);
    drag(at, at);
    ASSERT_EQ(tf->points().size(), 3u);
    ASSERT_EQ(tf->points().count(v1), 1u) << "added at the value under the mouse";
    EXPECT_EQ(tf->points().at(v1), osg::Vec4(before.r(), before.g(), before.b(), float(a1)));
    EXPECT_NEAR(v1, 100.0, 0.5);
    EXPECT_NEAR(a1, 0.5, 0.01);
    const TransferFunction::Points added = tf->points();

    // Drag it to (150, 0.25): the old value is gone, the new one holds the opacity under the mouse.
    const ImVec2 to = pixelOf(editor->screenPosition(150.0, 0.25));
    const auto [v2, a2] = editor->valueAt(to);
    drag(at, to);
    ASSERT_EQ(tf->points().size(), 3u);
    EXPECT_EQ(tf->points().count(v1), 0u);
    ASSERT_EQ(tf->points().count(v2), 1u);
    EXPECT_EQ(tf->points().at(v2).a(), float(a2));
    EXPECT_EQ(tf->points().at(v2).r(), before.r()) << "dragging the opacity leaves the colour";
    const TransferFunction::Points moved = tf->points();

    // A drag past a neighbour stops just before it.
    const ImVec2 far = pixelOf(editor->screenPosition(400.0, 0.25));
    drag(to, far);
    ASSERT_EQ(tf->points().size(), 3u);
    const double last = std::prev(tf->points().end(), 2)->first;
    EXPECT_LT(last, 255.0);
    EXPECT_GT(last, 254.99);
    // Undo the overshoot with Ctrl+Z.
    frame({ImVec2(300, 300), false, false, true});
    frame({ImVec2(300, 300)});
    EXPECT_EQ(tf->points(), moved);

    // Delete: a right-click on the point.
    rightClick(pixelOf(editor->screenPosition(v2, a2)));
    EXPECT_EQ(tf->points(), original);

    // Undo, undo, undo: back through the steps; redo forwards.
    ASSERT_TRUE(editor->history().undo());
    EXPECT_EQ(tf->points(), moved);
    ASSERT_TRUE(editor->history().undo());
    EXPECT_EQ(tf->points(), added);
    ASSERT_TRUE(editor->history().undo());
    EXPECT_EQ(tf->points(), original);
    EXPECT_FALSE(editor->history().canUndo());
    ASSERT_TRUE(editor->history().redo());
    EXPECT_EQ(tf->points(), added);
}

TEST_F(Editor, ChannelCurvesAreEditedIndependently)
{
    // On the red curve, a new point at 128 with red 0.9 leaves green, blue and opacity on their
    // lines through that value.
    editor->channel = TransferFunctionEditor::Channel::Red;
    const ImVec2 at = pixelOf(editor->screenPosition(128.0, 0.9));
    const auto [v, r] = editor->valueAt(at);
    const osg::Vec4 before = tf->evaluate(v);
    drag(at, at);
    ASSERT_EQ(tf->points().count(v), 1u);
    EXPECT_EQ(tf->points().at(v), osg::Vec4(float(r), before.g(), before.b(), before.a()));
}

TEST_F(Editor, LogarithmicOpacityAxisReachesTinyOpacities)
{
    // With the log axis the bottom quarter of the canvas spans 1e-4 .. 1e-3.
    editor->channel = TransferFunctionEditor::Channel::Alpha;
    editor->logOpacity = true;
    frame();
    const ImVec2 at = pixelOf(editor->screenPosition(60.0, 3e-4));
    const auto [v, a] = editor->valueAt(at);
    drag(at, at);
    ASSERT_EQ(tf->points().count(v), 1u);
    EXPECT_NEAR(tf->points().at(v).a(), 3e-4, 3e-5);
}

TEST_F(Editor, SaveThenLoadGivesTheIdenticalTransferFunction)
{
    ASSERT_TRUE(editor->applyPreset("CT bone"));
    editor->path = tempDirectory() + "/bone.tf";
    std::string error;
    ASSERT_TRUE(editor->save(error)) << error;
    const TransferFunction::Points saved = tf->points();
    const double lo = tf->domainMin(), hi = tf->domainMax();
    ASSERT_TRUE(editor->applyPreset("MRI"));
    ASSERT_NE(tf->points(), saved);
    ASSERT_TRUE(editor->load(error)) << error;
    EXPECT_EQ(tf->points(), saved);
    EXPECT_EQ(tf->domainMin(), lo);
    EXPECT_EQ(tf->domainMax(), hi);
    ASSERT_TRUE(editor->history().undo());  // the load is one step
    EXPECT_NE(tf->points(), saved);
}

TEST_F(Editor, SavingOverAnUnwritableFileFailsClearlyAndKeepsTheOldFile)
{
    editor->path = tempDirectory() + "/kept.tf";
    std::string error;
    ASSERT_TRUE(editor->save(error)) << error;
    std::ifstream in(editor->path);
    std::stringstream old;
    old << in.rdbuf();
    ASSERT_EQ(chmod(editor->path.c_str(), 0444), 0);
    ASSERT_TRUE(editor->applyPreset("MRI"));
    EXPECT_FALSE(editor->save(error));
    EXPECT_NE(error.find(editor->path), std::string::npos) << error;
    EXPECT_NE(editor->message().find("not saved"), std::string::npos);
    std::ifstream again(editor->path);
    std::stringstream now;
    now << again.rdbuf();
    EXPECT_EQ(now.str(), old.str()) << "the old file is intact";
}

TEST_F(Editor, ScreenshotShowsTheHistogramTheCurvesAndThePointsOverTheVolume)
{
    // The editor over a real dataset's histogram: grey histogram bars inside the canvas, the
    // white opacity curve, the colour strip, and the volume drawn beside the window.
    VOLREN_REQUIRE_SHARED_DATA();
    volume = readVolumeFile(sharedData("mri/ch2.nii.gz"));
    editor = std::make_unique<TransferFunctionEditor>(tf.get(), volume.get());
    ASSERT_TRUE(editor->applyPreset("MRI"));
    scene = new VolumeScene;
    scene->addChild(volumeNode(volume.get(), tf.get()).get());
    scene->addChild(overlay->node());
    frame();
    const Pixels p = frame();
    auto pixel = [&](const ImVec2& at) { return p.at(int(at.x), height - 1 - int(at.y)); };  // ImGui: y down
    int bars = 0, curve = 0, strip = 0, volumePixels = 0;
    const ImVec2 lo = editor->screenPosition(editor->viewMin, 1.0), hi = editor->screenPosition(editor->viewMax, 0.0);
    for (float y = lo.y + 2; y < hi.y - 12; y += 1.0f)
        for (float x = lo.x + 2; x < hi.x - 2; x += 1.0f) {
            const osg::Vec4 c = pixel(ImVec2(x, y));
            bars += std::abs(c.r() - 85 / 255.0f) < 0.03f && std::abs(c.g() - 85 / 255.0f) < 0.03f;
            curve += c.r() > 0.9f && c.g() > 0.9f && c.b() > 0.9f;
        }
    for (float x = lo.x + 2; x < hi.x - 2; x += 1.0f) strip += pixel(ImVec2(x, hi.y - 3)).r() > 0.3f;
    for (const osg::Vec4& c : p.rgba) volumePixels += c.a() > 0.5f && c.r() > c.b() + 0.05f;
    EXPECT_GT(bars, 500) << "histogram bars";
    EXPECT_GT(curve, 100) << "the opacity curve";
    EXPECT_GT(strip, 100) << "the colour strip";
    EXPECT_GT(volumePixels, 1000) << "the head beside the editor";
    EXPECT_GT(overlay->frames(), 2u);
}

/// What a handler may ask of the viewer: nothing here.
struct NoActions : osgGA::GUIActionAdapter
{
    void requestRedraw() override {}
    void requestContinuousUpdate(bool) override {}
    void requestWarpPointer(float, float) override {}
};

osg::ref_ptr<osgGA::GUIEventAdapter> event(osgGA::GUIEventAdapter::EventType type, double time, float x = 0, float y = 0)
{
    osg::ref_ptr<osgGA::GUIEventAdapter> e = new osgGA::GUIEventAdapter;
    e->setEventType(type);
    e->setTime(time);
    e->setWindowRectangle(0, 0, Editor::width, Editor::height);
    e->setInputRange(0, 0, Editor::width, Editor::height);
    e->setX(x);
    e->setY(y);
    e->setButton(osgGA::GUIEventAdapter::LEFT_MOUSE_BUTTON);
    e->setMouseYOrientation(osgGA::GUIEventAdapter::Y_INCREASING_UPWARDS);  // as osgViewer's windows send them
    return e;
}

TEST_F(Editor, WindowEventsReachImGuiAndThoseOnTheEditorAreConsumed)
{
    // An osgViewer's events, y upwards, become ImGui's mouse (y downwards); over the editor the
    // handler consumes them, so the trackball does not turn.
    NoActions actions;
    osgGA::GUIEventHandler& handler = *overlay->eventHandler();
    overlay->beforeFrame = nullptr;  // the handler feeds ImGui now
    const ImVec2 inside = pixelOf(editor->screenPosition(100.0, 0.5));
    handler.handle(*event(osgGA::GUIEventAdapter::MOVE, 0.9, inside.x, height - inside.y), actions);
    renderOrthoFromPlusZ(scene.get(), width, height, 40.0);  // a frame sees the mouse over the editor
    EXPECT_TRUE(handler.handle(*event(osgGA::GUIEventAdapter::PUSH, 1.0, inside.x, height - inside.y), actions));
    ImGui::SetCurrentContext(overlay->context());
    EXPECT_EQ(ImGui::GetIO().MousePos.x, inside.x);
    EXPECT_EQ(ImGui::GetIO().MousePos.y, inside.y);
    EXPECT_TRUE(ImGui::GetIO().MouseDown[0]);
    handler.handle(*event(osgGA::GUIEventAdapter::RELEASE, 1.1, inside.x, height - inside.y), actions);
    EXPECT_FALSE(ImGui::GetIO().MouseDown[0]);
    // Away from every ImGui window (after a frame has seen the mouse there): not consumed.
    handler.handle(*event(osgGA::GUIEventAdapter::MOVE, 1.2, width - 5.0f, 5.0f), actions);
    renderOrthoFromPlusZ(scene.get(), width, height, 40.0);
    EXPECT_FALSE(handler.handle(*event(osgGA::GUIEventAdapter::PUSH, 1.3, width - 5.0f, 5.0f), actions));
}

TEST(InteractionQualityPolicy, CoarserLevelOfDetailWhileInteractingFullLevelWhenIdle)
{
    osg::ref_ptr<VolumeNode> node = RenderFixture::volumeNode(constantVolume(VoxelType::UInt8, {4, 4, 4}, 1).get(),
                                                              constantTransferFunction(osg::Vec4(1, 1, 1, 0.1f)).get());
    osg::ref_ptr<InteractionQuality> policy = new InteractionQuality(node.get(), 0.3);
    NoActions actions;
    EXPECT_FALSE(policy->handle(*event(osgGA::GUIEventAdapter::PUSH, 1.0), actions)) << "never consumes";
    EXPECT_EQ(node->settings.lod, 1) << "the next mip level while interacting";
    policy->handle(*event(osgGA::GUIEventAdapter::DRAG, 1.1), actions);
    policy->handle(*event(osgGA::GUIEventAdapter::FRAME, 1.3), actions);
    EXPECT_EQ(node->settings.lod, 1) << "0.2 s after the last drag: still coarser";
    policy->handle(*event(osgGA::GUIEventAdapter::FRAME, 1.45), actions);
    EXPECT_EQ(node->settings.lod, 0) << "0.35 s after: the full level";
    EXPECT_FALSE(policy->lowered());

    node->settings.lod = 2;  // coarse already: one more
    policy->handle(*event(osgGA::GUIEventAdapter::SCROLL, 2.0), actions);
    EXPECT_EQ(node->settings.lod, 3);
    node->settings.lod = 1;  // the settings panel during the drag
    policy->handle(*event(osgGA::GUIEventAdapter::FRAME, 3.0), actions);
    EXPECT_EQ(node->settings.lod, 1) << "a level set meanwhile stays";
}

}  // namespace
}  // namespace volren::test
