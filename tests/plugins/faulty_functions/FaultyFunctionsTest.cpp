// The composition sweep fails where a composition is broken: each planted fault of this folder
// is reported for every composition that chooses it, with the check that caught it, while the
// same compositions without the fault pass (`volren permutations --render`, a subprocess with
// the plugin's folders in its environment).
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

namespace volren::test {
namespace {

/// What a sweep printed and how it exited.
struct Sweep
{
    int status = -1;
    std::vector<std::string> failed;  ///< its "FAILED ..." lines
    std::string output;
};

/// `volren permutations --render` over the compositions (no clip instances, no lights) that
/// choose every implementation of `where`, at most `count`, with `environment` set and `more`
/// options.
Sweep sweep(const std::string& environment, const std::vector<std::string>& where, int count, const std::string& more = "")
{
    std::string command = environment + " '" + VOLREN_BINARY_DIR + "/bin/volren' permutations --render --max-instances 0 "
                                                                   "--max-lights 0 --count " +
                          std::to_string(count) + " " + more;
    for (const std::string& w : where) command += " --where " + w;
    command += " 2>&1";
    Sweep s;
    if (FILE* pipe = popen(command.c_str(), "r")) {
        char buffer[4096];
        while (std::size_t n = std::fread(buffer, 1, sizeof(buffer), pipe)) s.output.append(buffer, n);
        const int raw = pclose(pipe);
        s.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    }
    std::istringstream lines(s.output);
    for (std::string line; std::getline(lines, line);)
        if (line.rfind("FAILED ", 0) == 0) s.failed.push_back(line);
    return s;
}

const std::string plugin =
    std::string("VOLREN_FUNCTION_PATH='") + FAULTY_LIBRARY_DIR + "' VOLREN_SHADER_PATH='" + FAULTY_SHADER_DIR + "'";

/// Compositions every check applies to: emission-absorption with real storage and sampling.
const std::vector<std::string> drawnSetting = {"RayTraversal=dvr_front_to_back", "Reconstruction=trilinear",
                                               "VolumeStorage=texture", "RaySetup=box_intersection"};

std::vector<std::string> with(std::vector<std::string> where, const std::string& more)
{
    where.push_back(more);
    return where;
}

/// Expects `s` to have failed `count` compositions, each once and by `check`, naming `fault`.
void expectCaught(const Sweep& s, const std::string& check, const std::string& fault, std::size_t count)
{
    EXPECT_EQ(s.status, 1) << s.output;
    ASSERT_EQ(s.failed.size(), count) << s.output;
    for (const std::string& line : s.failed) {
        EXPECT_NE(line.find(fault), std::string::npos) << line;
        EXPECT_NE(line.find(";: " + check + ": "), std::string::npos) << line;
    }
}

TEST(FaultyFunctions, TheFaultlessCompositionsPass)
{
    const Sweep s = sweep(plugin, with(drawnSetting, "Classification=tf1d"), 3);
    EXPECT_EQ(s.status, 0) << s.output;
    EXPECT_TRUE(s.failed.empty()) << s.output;
    EXPECT_NE(s.output.find("rendered 3, failures 0"), std::string::npos) << s.output;
}

TEST(FaultyFunctions, AnImplementationWhoseComposingThrowsFails)
{
    const Sweep s = sweep(plugin, with(drawnSetting, "Classification=compose_fails"), 3);
    expectCaught(s, "compose", "Classification=compose_fails", 3);
    EXPECT_NE(s.failed.front().find("no_such_file.glsl"), std::string::npos) << s.failed.front();
}

TEST(FaultyFunctions, AnImplementationThatDrawsNothingFails)
{
    expectCaught(sweep(plugin, with(drawnSetting, "Classification=draws_nothing"), 3), "drawn",
                 "Classification=draws_nothing", 3);
}

TEST(FaultyFunctions, AnImplementationThatWritesInfFails)
{
    expectCaught(sweep(plugin, {"RayTraversal=writes_inf"}, 3), "finite", "RayTraversal=writes_inf", 3);
}

TEST(FaultyFunctions, ABrokenGlslFileOnTheShaderPathFailsEveryCompositionThatUsesIt)
{
    const Sweep s = sweep(std::string("VOLREN_SHADER_PATH='") + BROKEN_SHADER_DIR + "'", {"Gradient=central"}, 3);
    expectCaught(s, "link", "Gradient=central", 3);
    EXPECT_NE(s.failed.front().find("Gradient/central.glsl"), std::string::npos) << s.failed.front();
    // The same compositions with the real file pass.
    const Sweep real = sweep("", {"Gradient=central"}, 3);
    EXPECT_EQ(real.status, 0) << real.output;
}

TEST(FaultyFunctions, ABrokenIncludeOnTheShaderPathOverridesItAndIsNoImplementation)
{
    const Sweep s = sweep(std::string("VOLREN_SHADER_PATH='") + BROKEN_INCLUDE_DIR + "'", {"Acceleration=occupancy"}, 2);
    expectCaught(s, "link", "Acceleration=occupancy", 2);
    // The same number of valid compositions as without it: the include is not an Acceleration.
    const Sweep real = sweep("", {"Acceleration=occupancy"}, 2);
    EXPECT_EQ(real.status, 0) << real.output;
    const auto spaceLine = [](const std::string& out) { return out.substr(0, out.find(" valid compositions")); };
    EXPECT_EQ(spaceLine(s.output.substr(s.output.find("volren permutations:"))),
              spaceLine(real.output.substr(real.output.find("volren permutations:"))));
}

TEST(FaultyFunctions, AWrongColourInAnExactImplementationFailsAgainstTheReference)
{
    // Red and blue swapped in tf1d: every other check passes; the reference comparison fails.
    const std::vector<std::string> where = with(drawnSetting, "Classification=tf1d");
    const Sweep s = sweep(std::string("VOLREN_SHADER_PATH='") + WRONG_VALUE_DIR + "'", where, 3, "--modelled");
    expectCaught(s, "reference", "Classification=tf1d", 3);
    EXPECT_NE(s.failed.front().find("against the CPU reference"), std::string::npos) << s.failed.front();
    // The same compositions with the real file are compared with the reference and pass.
    const Sweep real = sweep("", where, 3, "--modelled");
    EXPECT_EQ(real.status, 0) << real.output;
    EXPECT_NE(real.output.find(" reference 3"), std::string::npos) << real.output;
}

TEST(FaultyFunctions, SkippingLeapsOverWhatTheClassificationMirrorCallsEmpty)
{
    // The probe classification shows values below 0.5 while its mirror calls them invisible:
    // occupancy skipping that leaps over those cells draws less than the same composition
    // without skipping, so the sweep's bit-identical comparison with Acceleration=null fails.
    const std::vector<std::string> where = with(with(drawnSetting, "Classification=hidden_below_half"), "Acceleration=occupancy");
    expectCaught(sweep(plugin, where, 3), "acceleration", "Acceleration=occupancy", 3);
    // An occupancy leap that never leaps (planted on the shader path) skips nothing: the same
    // compositions then pass, which is why the probe, not "skipping changes nothing", is the test.
    const Sweep never = sweep(plugin + " VOLREN_SHADER_PATH='" + NEVER_LEAPS_DIR + ":" + FAULTY_SHADER_DIR + "'", where, 3);
    EXPECT_EQ(never.status, 0) << never.output;
    EXPECT_NE(never.output.find("acceleration 3"), std::string::npos) << never.output;
}

}  // namespace
}  // namespace volren::test
