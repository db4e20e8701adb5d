// The shader compositor: composition keys, program caching, source assembly and the errors
// that name slot, implementation and file.
#include <volume_renderer/SampleDistance.h>
#include <volume_renderer/ShaderCompositor.h>
#include <volume_renderer/Slots.h>
#include <volume_renderer/VolumeScene.h>

#include "TestData.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <vector>

namespace volren::test {
namespace {

TEST(Compositor, KeyNamesEverySlotWithDefaultsFilledIn)
{
    Composition c;
    c.choice["Jitter"] = "texture";
    const std::string key = c.key();
    for (const SlotInfo& s : slots()) EXPECT_NE(key.find(s.name + "="), std::string::npos) << s.name;
    EXPECT_NE(key.find("Jitter=texture;"), std::string::npos);
    EXPECT_NE(key.find("RayTraversal=dvr_front_to_back;"), std::string::npos);
    EXPECT_NE(key, Composition{}.key());
}

TEST(Compositor, SameCompositionIsBuiltOnceAndReused)
{
    ShaderCompositor compositor;
    Composition a, b;
    a.choice["Jitter"] = "null";
    b.choice["Jitter"] = "null";
    auto pa = compositor.program(a);
    auto pb = compositor.program(b);
    EXPECT_EQ(pa.get(), pb.get());
    EXPECT_EQ(compositor.programCount(), 1u);
    compositor.program(Composition{});
    EXPECT_EQ(compositor.programCount(), 2u);
}

TEST(Compositor, ComposedSourceHoldsEachChosenFileOnceWithLineMarkers)
{
    ShaderCompositor compositor;
    Composition c;
    c.choice["Jitter"] = "hash";
    auto p = compositor.program(c);
    const std::string& src = p->fragmentSource;
    EXPECT_EQ(src.rfind("#version 430 core", 0), 0u) << "version must come first";
    EXPECT_NE(src.find("float volren_jitter(vec2 fragCoord)\n{\n    uvec2 p"), std::string::npos);
    const std::string definition = "float volren_jitter(vec2 fragCoord)\n{";
    EXPECT_EQ(src.find(definition), src.rfind(definition)) << "exactly one Jitter implementation is included";
    // Uniforms are declared once, by the compositor.
    const std::string decl = "uniform vec3 volren_worldSize;";
    EXPECT_NE(src.find(decl), std::string::npos);
    EXPECT_EQ(src.find(decl), src.rfind(decl));
    // header, numerics, slots.glsl, the traversal's march.glsl, the ray setup's ray.glsl and the
    // null Acceleration's every_step.glsl includes, one per slot
    ASSERT_EQ(p->sourceNames.size(), 6u + slots().size());
    EXPECT_EQ(std::count(p->sourceNames.begin(), p->sourceNames.end(), "Acceleration/every_step.glsl"), 1);
    EXPECT_EQ(p->sourceNames[p->sourceNames.size() - 2], "RaySetup/ray.glsl");
    EXPECT_EQ(p->sourceNames.back(), "RaySetup/box_intersection.glsl");
    EXPECT_EQ(p->textureUnits.at("volren_volume"), 0);
    EXPECT_EQ(p->textureUnits.at("volren_transferFunction"), 1);
}

TEST(Compositor, UnknownImplementationIsAnErrorNamingSlotAndKnownOnes)
{
    ShaderCompositor compositor;
    Composition c;
    c.choice["Jitter"] = "blue_noise_from_mars";
    try {
        compositor.program(c);
        FAIL() << "expected an error";
    } catch (const std::runtime_error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("slot Jitter"), std::string::npos) << what;
        EXPECT_NE(what.find("blue_noise_from_mars"), std::string::npos) << what;
        EXPECT_NE(what.find("hash"), std::string::npos) << what;
    }
    Composition badSlot;
    badSlot.choice["Teleport"] = "null";
    EXPECT_THROW(compositor.program(badSlot), std::runtime_error);
}

TEST(Compositor, MissingShaderFileNamesImplementationAndPath)
{
    ShaderFunctionRegistry registry;
    registry.addBuiltins();
    registry.add({.slot = "Jitter", .name = "hash", .file = "Jitter/does_not_exist.glsl"});
    ShaderCompositor compositor(registry);
    try {
        compositor.program(Composition{});
        FAIL() << "expected an error";
    } catch (const std::runtime_error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("slot Jitter, implementation hash"), std::string::npos) << what;
        EXPECT_NE(what.find("Jitter/does_not_exist.glsl"), std::string::npos) << what;
    }
}

TEST(Compositor, ShaderPathOverridesTheInstalledFiles)
{
    const std::string dir = tempDirectory();
    std::filesystem::create_directories(dir + "/Jitter");
    std::ofstream(dir + "/Jitter/hash.glsl") << "// override\nfloat volren_jitter(vec2 f) { return 0.25; }\n";
    setenv("VOLREN_SHADER_PATH", dir.c_str(), 1);
    ShaderCompositor compositor;
    Composition c;
    c.choice["Jitter"] = "hash";
    const std::string src = compositor.program(c)->fragmentSource;
    unsetenv("VOLREN_SHADER_PATH");
    EXPECT_NE(src.find("return 0.25;"), std::string::npos);
}

TEST(Compositor, TheSetTraversalsLoopsOverMembersAreWrittenOutPerMember)
{
    // Each loop `for (int k = 0; k < VOLREN_MEMBER_COUNT...)` of MultiVolume/sum_of_media.glsl
    // becomes one block per member with a constant k (so a dispatcher call reaches one member's
    // code), and the file's lines after each loop keep their numbers (a #line after it).
    ShaderCompositor compositor;
    Composition set;
    set.choice["RayTraversal"] = "sum_of_media";
    set.members = {Composition{}, Composition{}, Composition{}};
    const std::string src = compositor.program(set)->fragmentSource;
    EXPECT_EQ(src.find("k < VOLREN_MEMBER_COUNT"), std::string::npos);
    for (int k = 0; k < 3; ++k) EXPECT_NE(src.find("do { const int k = " + std::to_string(k) + ";"), std::string::npos) << k;
    EXPECT_EQ(src.find("do { const int k = 3;"), std::string::npos);
    // The file's own lines: each loop's closing line number follows it as a #line.
    std::ifstream file(std::string(VOLREN_SOURCE_DIR) + "/shaders/MultiVolume/sum_of_media.glsl");
    std::vector<std::string> lines;
    for (std::string line; std::getline(file, line);) lines.push_back(line);
    int loops = 0;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        if (lines[i].find("k < VOLREN_MEMBER_COUNT") == std::string::npos) continue;
        ++loops;
        const std::string indent = lines[i].substr(0, lines[i].find_first_not_of(' '));
        std::size_t close = i + 1;
        while (close < lines.size() && lines[close] != indent + "}") ++close;
        ASSERT_LT(close, lines.size()) << "loop at line " << i + 1;
        EXPECT_NE(src.find("} while (false);\n#line " + std::to_string(close + 1) + "\n"), std::string::npos)
            << "loop at line " << i + 1 << " closing at line " << close + 1;
    }
    EXPECT_EQ(loops, 4);
}

TEST(Compositor, DriverLogLinesAreMappedToShaderFiles)
{
    ShaderCompositor compositor;
    auto p = compositor.program(Composition{});
    const std::size_t traversal = p->sourceNames.size() - 3;  // RayTraversal, ray.glsl, RaySetup
    const std::string mesa = std::to_string(traversal) + ":17(5): error: `foo' undeclared\n";
    const std::string nvidia = std::to_string(traversal) + "(17) : error C1008: undefined variable \"foo\"\n";
    EXPECT_EQ(ShaderCompositor::explainLog(mesa, *p), "RayTraversal/dvr_front_to_back.glsl:17: error: `foo' undeclared\n");
    EXPECT_EQ(ShaderCompositor::explainLog(nvidia, *p),
              "RayTraversal/dvr_front_to_back.glsl:17 : error C1008: undefined variable \"foo\"\n");
}

TEST(Compositor, SceneAnalysisPicksJitterFromTheNodeSettings)
{
    osg::ref_ptr<VolumeScene> scene = new VolumeScene;
    osg::ref_ptr<VolumeNode> node = new VolumeNode;
    EXPECT_EQ(scene->policy().choose(node->settings, {}, scene->pass).composition.functionFor("Jitter"), "hash");
    node->settings.functions["Jitter"] = "null";
    EXPECT_EQ(scene->policy().choose(node->settings, {}, scene->pass).composition.functionFor("Jitter"), "null");
}

TEST(Compositor, SampleDistanceIsAFactorOfTheSmallestSpacingAndBounded)
{
    osg::ref_ptr<Volume> volume = constantVolume(VoxelType::UInt8, {10, 10, 10}, 1, {0.5, 2.0, 3.0});
    osg::ref_ptr<VolumeNode> node = new VolumeNode;
    node->setVolume(volume.get());
    node->settings.sampleDistanceFactor = 0.25;
    EXPECT_DOUBLE_EQ(effectiveSampleDistance(*node), 0.125);
    node->settings.sampleDistance = 0.7;
    EXPECT_DOUBLE_EQ(effectiveSampleDistance(*node), 0.7);
    node->settings.sampleDistance = 1e-12;  // absurd: coarsened so a ray takes at most maxSteps samples
    EXPECT_DOUBLE_EQ(effectiveSampleDistance(*node), volume->worldSize().length() / maxStepsPerRay);
}

}  // namespace
}  // namespace volren::test
