#include <volume_gui/ImGuiOverlay.h>

#include <imgui.h>
#include <backends/imgui_impl_opengl3.h>

#include <osg/Depth>
#include <osg/Drawable>
#include <osg/State>
#include <osg/Timer>

namespace volren {

/// Runs and renders one ImGui frame per draw.
class ImGuiOverlay::Drawable : public osg::Drawable
{
public:
    explicit Drawable(ImGuiOverlay* owner) : _owner(owner)
    {
        setUseDisplayList(false);
        setUseVertexBufferObjects(false);
        setCullingActive(false);
        setDataVariance(osg::Object::DYNAMIC);
    }
    Drawable(const Drawable& other, const osg::CopyOp& op) : osg::Drawable(other, op), _owner(other._owner) {}
    META_Object(volren, Drawable)

    void drawImplementation(osg::RenderInfo& info) const override
    {
        ImGuiOverlay& o = *_owner;
        ImGui::SetCurrentContext(o._context);
        ImGuiIO& io = ImGui::GetIO();
        if (!o._initialised) {
            ImGui_ImplOpenGL3_Init("#version 330 core");
            o._initialised = true;
        }
        osg::State& state = *info.getState();
        if (const osg::Viewport* vp = state.getCurrentViewport())
            io.DisplaySize = ImVec2(float(vp->width()), float(vp->height()));
        const double now = osg::Timer::instance()->time_s();
        io.DeltaTime = o._lastTime < 0.0 ? 1.0f / 60.0f : float(std::max(1e-4, now - o._lastTime));
        o._lastTime = now;
        if (o.beforeFrame) o.beforeFrame(io);
        ImGui_ImplOpenGL3_NewFrame();
        ImGui::NewFrame();
        o._ui();
        ImGui::Render();
        ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
        ++o._frames;
        // The backend restored the GL state it changed; OSG's own record of the last program is
        // all that may be stale (the backend binds its program through GL directly).
        state.setLastAppliedProgramObject(nullptr);
    }

private:
    Drawable() = default;
    ImGuiOverlay* _owner = nullptr;
};

/// osgGA events -> ImGui IO.
class ImGuiOverlay::Handler : public osgGA::GUIEventHandler
{
public:
    explicit Handler(ImGuiOverlay* owner) : _owner(owner) {}

    bool handle(const osgGA::GUIEventAdapter& ea, osgGA::GUIActionAdapter&) override
    {
        ImGui::SetCurrentContext(_owner->_context);
        ImGuiIO& io = ImGui::GetIO();
        using E = osgGA::GUIEventAdapter;
        const float y = ea.getMouseYOrientation() == E::Y_INCREASING_UPWARDS ? ea.getWindowHeight() - ea.getY() : ea.getY();
        switch (ea.getEventType()) {
        case E::MOVE:
        case E::DRAG:
            io.MousePos = ImVec2(ea.getX(), y);
            return io.WantCaptureMouse;
        case E::PUSH:
        case E::RELEASE: {
            io.MousePos = ImVec2(ea.getX(), y);
            const int button = ea.getButton() == E::LEFT_MOUSE_BUTTON ? 0 : ea.getButton() == E::RIGHT_MOUSE_BUTTON ? 1 : 2;
            io.MouseDown[button] = ea.getEventType() == E::PUSH;
            return io.WantCaptureMouse;
        }
        case E::SCROLL:
            io.MouseWheel += ea.getScrollingMotion() == E::SCROLL_UP ? 1.0f : ea.getScrollingMotion() == E::SCROLL_DOWN ? -1.0f : 0.0f;
            return io.WantCaptureMouse;
        case E::KEYDOWN:
        case E::KEYUP: {
            const bool down = ea.getEventType() == E::KEYDOWN;
            const int key = ea.getUnmodifiedKey();
            if (key >= 0 && key < int(IM_ARRAYSIZE(io.KeysDown))) io.KeysDown[key] = down;
            io.KeyCtrl = (ea.getModKeyMask() & E::MODKEY_CTRL) != 0;
            io.KeyShift = (ea.getModKeyMask() & E::MODKEY_SHIFT) != 0;
            if (down && ea.getKey() > 0 && ea.getKey() < 0x10000 && !io.KeyCtrl) io.AddInputCharacter(unsigned(ea.getKey()));
            return io.WantCaptureKeyboard;
        }
        default:
            return false;
        }
    }

private:
    ImGuiOverlay* _owner;
};

ImGuiOverlay::ImGuiOverlay(std::function<void()> ui) : _ui(std::move(ui))
{
    ImGuiContext* previous = ImGui::GetCurrentContext();
    _context = ImGui::CreateContext();
    ImGui::SetCurrentContext(_context);
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // no imgui.ini beside the user's files
    // Keys by osgGA key code (letters are their ASCII codes there).
    io.KeyMap[ImGuiKey_Tab] = osgGA::GUIEventAdapter::KEY_Tab & 0x1FF;
    io.KeyMap[ImGuiKey_Backspace] = osgGA::GUIEventAdapter::KEY_BackSpace & 0x1FF;
    io.KeyMap[ImGuiKey_Delete] = osgGA::GUIEventAdapter::KEY_Delete & 0x1FF;
    io.KeyMap[ImGuiKey_Enter] = osgGA::GUIEventAdapter::KEY_Return & 0x1FF;
    io.KeyMap[ImGuiKey_Escape] = osgGA::GUIEventAdapter::KEY_Escape & 0x1FF;
    io.KeyMap[ImGuiKey_LeftArrow] = osgGA::GUIEventAdapter::KEY_Left & 0x1FF;
    io.KeyMap[ImGuiKey_RightArrow] = osgGA::GUIEventAdapter::KEY_Right & 0x1FF;
    io.KeyMap[ImGuiKey_Z] = 'z';
    io.KeyMap[ImGuiKey_Y] = 'y';
    io.KeyMap[ImGuiKey_A] = 'a';
    io.KeyMap[ImGuiKey_C] = 'c';
    io.KeyMap[ImGuiKey_V] = 'v';
    io.KeyMap[ImGuiKey_X] = 'x';
    ImGui::SetCurrentContext(previous ? previous : _context);

    _geode = new osg::Geode;
    _geode->setName("volren ImGui overlay");
    _geode->addDrawable(new Drawable(this));
    _geode->setCullingActive(false);
    osg::StateSet* ss = _geode->getOrCreateStateSet();
    ss->setRenderBinDetails(1000, "RenderBin");
    ss->setMode(GL_DEPTH_TEST, osg::StateAttribute::OFF);
    _handler = new Handler(this);
}

osgGA::GUIEventHandler* ImGuiOverlay::eventHandler()
{
    return _handler.get();
}

ImGuiOverlay::~ImGuiOverlay()
{
    // The backend's GL objects die with the GL context it drew in (gone by now, or not current:
    // its deletes are then no-ops); its own data and the ImGui context are freed here.
    ImGuiContext* previous = ImGui::GetCurrentContext();
    ImGui::SetCurrentContext(_context);
    if (_initialised) ImGui_ImplOpenGL3_Shutdown();
    ImGui::DestroyContext(_context);
    if (previous != _context) ImGui::SetCurrentContext(previous);
}

}  // namespace volren
