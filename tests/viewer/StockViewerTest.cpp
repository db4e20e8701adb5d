// Debian's stock osgviewer shows volren scenes and bare volume files, volumes mixed with polygons,
// on a virtual X display (Xvfb): the only test that needs a window; everything else is EGL.
// The screen is read from Xvfb's frame-buffer file (-fbdir) with netpbm's xwdtopnm.
#include "TestData.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <functional>
#include <spawn.h>
#include <string>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <vector>

extern char** environ;

namespace volren::test {
namespace {

const std::string sceneFolder = std::string(VOLREN_SOURCE_DIR) + "/scenes";

/// A child process, killed when this goes out of scope.
class Child
{
public:
    Child(std::vector<std::string> args, const std::vector<std::string>& extraEnv = {})
    {
        std::vector<char*> argv;
        for (std::string& a : args) argv.push_back(a.data());
        argv.push_back(nullptr);
        std::vector<std::string> env = extraEnv;
        for (char** e = environ; *e; ++e) env.push_back(*e);  // the extra values come first and win
        std::vector<char*> envp;
        for (std::string& e : env) envp.push_back(e.data());
        envp.push_back(nullptr);
        _env = std::move(env);
        if (posix_spawnp(&_pid, argv[0], nullptr, nullptr, argv.data(), envp.data()) != 0) _pid = -1;
    }
    ~Child()
    {
        if (_pid <= 0) return;
        ::kill(_pid, SIGTERM);
        ::waitpid(_pid, nullptr, 0);
    }
    bool started() const { return _pid > 0; }
    bool running() const { return _pid > 0 && ::waitpid(_pid, nullptr, WNOHANG) == 0; }

private:
    pid_t _pid = -1;
    std::vector<std::string> _env;
};

struct Screen
{
    int width = 0, height = 0;
    std::vector<unsigned char> rgb;
    int count(const std::function<bool(int, int, int)>& test) const
    {
        int n = 0;
        for (std::size_t i = 0; i + 2 < rgb.size(); i += 3) n += test(rgb[i], rgb[i + 1], rgb[i + 2]);
        return n;
    }
};

/// An Xvfb server with its screen in a file; display ":N" once started.
class VirtualDisplay
{
public:
    VirtualDisplay() : _dir(tempDirectory())
    {
        const std::string displayFile = _dir + "/display";
        // -displayfd picks a free display number and writes it to the given descriptor.
        _server = std::make_unique<Child>(std::vector<std::string>{
            "sh", "-c", "exec Xvfb -displayfd 3 -screen 0 400x300x24 -fbdir '" + _dir + "' -nolisten tcp 3>'" + displayFile + "'"});
        for (int i = 0; i < 100 && display.empty(); ++i) {
            std::this_thread::sleep_for(std::chrono::milliseconds(100));
            std::string number;
            std::ifstream(displayFile) >> number;
            if (!number.empty()) display = ":" + number;
        }
    }
    /// The screen now (empty when it cannot be read).
    Screen capture() const
    {
        Screen s;
        const std::string ppm = _dir + "/screen.ppm";
        if (std::system(("xwdtopnm '" + _dir + "/Xvfb_screen0' > '" + ppm + "' 2>/dev/null").c_str()) != 0) return s;
        auto in = OIIO::ImageInput::open(ppm);
        if (!in) return s;
        s.width = in->spec().width;
        s.height = in->spec().height;
        s.rgb.resize(std::size_t(s.width) * s.height * 3);
        in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, s.rgb.data());
        return s;
    }
    std::string display;

private:
    std::string _dir;
    std::unique_ptr<Child> _server;
};

using Check = std::function<std::string(const Screen&)>;  // "" when the screen shows what it should

/// Runs osgviewer on `input` and waits (up to 90 s) until two captures a second apart both pass
/// `check`; returns the last check's complaint ("" = passed).
std::string viewerShows(const std::string& input, const Check& check)
{
    VirtualDisplay x;
    if (x.display.empty()) return "Xvfb did not start";
    Child viewer({"osgviewer", "--window", "0", "0", "400", "300", input},
                 {"DISPLAY=" + x.display, "OSG_LIBRARY_PATH=" + std::string(VOLREN_BINARY_DIR) + "/lib"});
    if (!viewer.started()) return "osgviewer did not start";
    std::string complaint = "nothing captured";
    int passes = 0;
    const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(90);
    while (std::chrono::steady_clock::now() < end) {
        std::this_thread::sleep_for(std::chrono::seconds(1));
        if (!viewer.running()) return "osgviewer exited";
        const Screen screen = x.capture();
        complaint = screen.rgb.empty() ? "cannot read the screen" : check(screen);
        passes = complaint.empty() ? passes + 1 : 0;
        if (passes >= 2) return "";
    }
    return complaint;
}

std::string atLeast(const Screen& s, const char* what, int wanted, const std::function<bool(int, int, int)>& test)
{
    const int n = s.count(test);
    return n >= wanted ? "" : std::string(what) + ": " + std::to_string(n) + " pixels, expected at least " + std::to_string(wanted) + "; ";
}

bool toolsPresent()
{
    return std::system("command -v Xvfb >/dev/null && command -v xwdtopnm >/dev/null && command -v osgviewer >/dev/null") == 0;
}

/// Skips without the tools, except under CI (which installs them through tools/setup.sh).
#define VOLREN_REQUIRE_XVFB()                                                                      \
    if (!toolsPresent()) {                                                                         \
        if (std::getenv("CI")) FAIL() << "Xvfb, xwdtopnm (netpbm) or osgviewer missing";          \
        GTEST_SKIP() << "Xvfb, xwdtopnm (netpbm) or osgviewer missing: tools/setup.sh installs them"; \
    }

// osgviewer clears to (51, 51, 102).

TEST(StockOsgviewer, ShowsABareVolumeFileAsItsDefaultScene)
{
    VOLREN_REQUIRE_SHARED_DATA();
    VOLREN_REQUIRE_XVFB();
    const std::string complaint = viewerShows(sharedData("mri/ch2.nii.gz"), [](const Screen& s) {
        return atLeast(s, "skin-coloured head", 8000, [](int r, int g, int b) { return r > b + 20 && g > 40; });
    });
    EXPECT_EQ(complaint, "");
}

TEST(StockOsgviewer, ShowsTheInstrumentMixedWithTheVessels)
{
    VOLREN_REQUIRE_SHARED_DATA();
    VOLREN_REQUIRE_XVFB();
    const std::string complaint = viewerShows(sceneFolder + "/ct-instrument.osgt", [](const Screen& s) {
        return atLeast(s, "red vessels", 2000, [](int r, int, int b) { return r > b + 20; }) +
               atLeast(s, "the blue-grey rod", 100, [](int r, int g, int b) { return g >= r + 15 && b >= g + 30; });
    });
    EXPECT_EQ(complaint, "");
}

TEST(StockOsgviewer, KeepsShowingThePolygonModelFrameAfterFrame)
{
    // The glider is a display-list model drawn before the volume; it once vanished from the
    // second frame on. Two captures a second apart (many frames) must both show it.
    VOLREN_REQUIRE_SHARED_DATA();
    VOLREN_REQUIRE_XVFB();
    const std::string complaint = viewerShows(sceneFolder + "/isosurface-mesh.osgt", [](const Screen& s) {
        return atLeast(s, "orange glider", 150, [](int r, int g, int b) { return r > g + 25 && r > b + 60; }) +
               atLeast(s, "green-grey isosurface", 3000, [](int r, int g, int b) { return g > r + 10 && g > b + 10; });
    });
    EXPECT_EQ(complaint, "");
}

}  // namespace
}  // namespace volren::test
