// Kinds of auxiliary data are declared beside the implementations that need them (AuxKind.h):
// every need names a declared kind, the registry refuses a kind that says not how it is made, an
// undeclared need is named when a program is bound, and the pass (ProgramBinder, VolumeScene,
// GeometryShadows, BuiltVolumes) names no kind, slot or sampler: it reads the declarations.
#include <volume_renderer/ShaderFunctionRegistry.h>
#include <volume_renderer/Slots.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <stdexcept>

namespace fs = std::filesystem;

namespace volren::test {
namespace {

/// Every kind the registered implementations need.
std::set<std::string> neededKinds()
{
    std::set<std::string> kinds;
    const ShaderFunctionRegistry& registry = ShaderFunctionRegistry::instance();
    for (const SlotInfo& slot : slots())
        for (const std::string& name : registry.allNames(slot.name))
            for (const std::string& kind : registry.find(slot.name, name)->needs) kinds.insert(kind);
    return kinds;
}

TEST(AuxKinds, EveryNeedNamesADeclaredKind)
{
    const ShaderFunctionRegistry& registry = ShaderFunctionRegistry::instance();
    EXPECT_TRUE(registry.undeclaredNeeds().empty()) << registry.undeclaredNeeds().front();
    const std::set<std::string> kinds = neededKinds();
    EXPECT_GE(kinds.size(), 12u);
    for (const std::string& kind : kinds) EXPECT_NE(registry.auxKind(kind), nullptr) << kind;
    // What each says of itself, as the built-in declarations state it.
    const AuxKind* light = registry.auxKind("light volume");
    ASSERT_TRUE(light && light->build);
    EXPECT_TRUE(light->darkensGeometry);
    EXPECT_TRUE(light->build->readsLights);
    EXPECT_FALSE(light->build->mipmapped);
    const AuxKind* chain = registry.auxKind("opacity mip chain");
    ASSERT_TRUE(chain && chain->build);
    EXPECT_FALSE(chain->darkensGeometry);
    EXPECT_TRUE(chain->build->mipmapped);
    EXPECT_EQ(chain->build->wrap, osg::Texture::CLAMP_TO_BORDER);
    EXPECT_EQ(registry.auxKind("depth texture")->scope, AuxScope::Camera);
    EXPECT_EQ(registry.auxKind("geometry shadow map")->scope, AuxScope::GeometryFromLights);
    EXPECT_LT(registry.auxKind("brick pool")->order, registry.auxKind("occupancy grid")->order)
        << "storage refines the level before the grids are shaped by it";
    EXPECT_TRUE(registry.darkensGeometry(*registry.find("Shadowing", "light_volume")));
    EXPECT_FALSE(registry.darkensGeometry(*registry.find("Shadowing", "ray")));
    EXPECT_FALSE(registry.darkensGeometry(*registry.find("Shadowing", "cone")));
}

TEST(AuxKinds, TheRegistryRefusesAKindThatSaysNotHowItIsMade)
{
    ShaderFunctionRegistry registry;
    auto refused = [&registry](AuxKind kind) {
        try {
            registry.addAuxKind(std::move(kind));
        } catch (const std::logic_error& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_NE(refused({.name = "nothing"}).find("'nothing' must say how it is made"), std::string::npos);
    EXPECT_NE(refused({.name = "both", .provide = [](AuxRequest&) -> osg::Texture* { return nullptr; },
                       .build = AuxBuild{.sampler = "volren_both",
                                         .dims = [](const osg::Vec3i& d, const BindContext&) { return d; },
                                         .plan = [](const BindContext&, const osg::Vec3d&, const osg::Vec3i&) {
                                             return std::vector<BuildDispatch>{};
                                         }}})
                  .find("'both' must say how it is made"),
              std::string::npos);
    EXPECT_NE(refused({.name = "screen", .scope = AuxScope::Camera}).find("a Camera kind: perCamera"), std::string::npos);
    EXPECT_NE(refused({.name = "half", .build = AuxBuild{.sampler = "volren_half"}}).find("needs a sampler, dims, channels and a plan"),
              std::string::npos);
    EXPECT_EQ(refused({.name = "shadows", .scope = AuxScope::GeometryFromLights}), "");
    EXPECT_NE(refused({.name = "shadows", .scope = AuxScope::GeometryFromLights}).find("'shadows' is declared twice"),
              std::string::npos);
}

TEST(AuxKinds, AnUndeclaredNeedIsNamedWithItsImplementation)
{
    ShaderFunctionRegistry registry;
    registry.add({.slot = "Shadowing", .name = "wanting", .needs = {"a volume of wishes"}});
    const ShaderFunction& f = *registry.find("Shadowing", "wanting");
    try {
        registry.auxKindsOf(f);
        ADD_FAILURE() << "no error";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("Shadowing wanting needs auxiliary data 'a volume of wishes', a kind no one declared"),
                  std::string::npos)
            << e.what();
    }
    ASSERT_EQ(registry.undeclaredNeeds().size(), 1u);
}

/// "file:line: text" of each line of `files` that quotes one of `words`.
std::vector<std::string> quoting(const std::vector<fs::path>& files, const std::set<std::string>& words)
{
    std::vector<std::string> found;
    for (const fs::path& p : files) {
        std::ifstream in(p);
        EXPECT_TRUE(in) << p;
        std::string line;
        for (int n = 1; std::getline(in, line); ++n)
            for (const std::string& w : words)
                if (line.find('"' + w + '"') != std::string::npos || line.find("\"volren_") != std::string::npos)
                    found.push_back(p.filename().string() + ":" + std::to_string(n) + ": " + line);
    }
    return found;
}

/// Kind names, slot names and the renderer's sampler prefix: what the pass must not name.
std::set<std::string> passMustNotName()
{
    std::set<std::string> words = neededKinds();
    for (const SlotInfo& slot : slots()) words.insert(slot.name);
    return words;
}

TEST(AuxKinds, ThePassNamesNoKindSlotOrSampler)
{
    const fs::path src = fs::path(VOLREN_SOURCE_DIR) / "plugins/volume_renderer/src";
    const std::vector<std::string> found = quoting({src / "pass/ProgramBinder.cpp", src / "pass/VolumeScene.cpp",
                                                    src / "pass/GeometryShadows.cpp", src / "resources/BuiltVolumes.cpp"},
                                                   passMustNotName());
    std::string list;
    for (const std::string& f : found) list += "\n  " + f;
    EXPECT_TRUE(found.empty()) << "the pass names kinds, slots or samplers:" << list;
}

TEST(AuxKinds, TheScanFindsANameWhereThereIsOne)
{
    const fs::path planted = fs::temp_directory_path() / "volren_aux_scan.cpp";
    std::ofstream(planted) << "int a;\nauto t = c.aux.at(\"light volume\");\nauto f = find(\"Shadowing\", n);\n";
    const std::vector<std::string> found = quoting({planted}, passMustNotName());
    ASSERT_EQ(found.size(), 2u);
    EXPECT_NE(found[0].find(":2:"), std::string::npos) << found[0];
    fs::remove(planted);
}

}  // namespace
}  // namespace volren::test
