// The composition policy: defaults from what the scene offers, clip shapes by their kind, ray
// sharing, multi-volume set compositions, validity rules with reasons, and the traits each
// implementation declares checked against its GLSL source.
#include <volume_renderer/CompositionPolicy.h>
#include <volume_renderer/Slots.h>

#include <volume_model/ClipBoxNode.h>
#include <volume_model/ClipEllipsoidNode.h>
#include <volume_model/ClipPlaneNode.h>
#include <volume_model/RenderSettings.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

namespace volren::test {
namespace {

SceneOffer offerWith(std::size_t lights, std::vector<const ClipNode*> clips = {}, bool opaque = false)
{
    SceneOffer offer;
    offer.lights.resize(lights);
    for (const ClipNode* c : clips) offer.clips.push_back({c, osg::Matrixd()});
    offer.opaqueGeometry = opaque;
    return offer;
}

TEST(CompositionPolicy, LightsBringLitShadingAGradientAndNothingElse)
{
    const CompositionPolicy policy;
    const Composition unlit = policy.choose({}, offerWith(0), {}).composition;
    for (const char* slot : {"Shading", "Illumination", "Gradient", "GradientInput", "Shadowing"})
        EXPECT_EQ(unlit.functionFor(slot), "null") << slot;
    EXPECT_EQ(unlit.functionFor("RayTraversal"), "dvr_front_to_back");
    EXPECT_EQ(unlit.functionFor("Jitter"), "hash");
    EXPECT_EQ(unlit.lightCount, 0u);

    const Composition lit = policy.choose({}, offerWith(3), {}).composition;
    EXPECT_EQ(lit.functionFor("Shading"), "lighting");
    EXPECT_EQ(lit.functionFor("Illumination"), "blinn_phong");
    EXPECT_EQ(lit.functionFor("Gradient"), "central");
    EXPECT_EQ(lit.functionFor("GradientInput"), "scalar");
    EXPECT_EQ(lit.lightCount, 3u);
    EXPECT_EQ(policy.choose({}, offerWith(20), {}).composition.lightCount, CompositionPolicy::maxLights);

    PassSettings dark;
    dark.lighting = false;
    EXPECT_EQ(policy.choose({}, offerWith(3), dark).composition.key(), unlit.key()) << "lighting=off ignores lights";

    RenderSettings mip;
    mip.functions["RayTraversal"] = "mip";
    const Composition projected = policy.choose(mip, offerWith(3), {}).composition;
    EXPECT_EQ(projected.functionFor("Shading"), "null") << "a traversal that never shades gets no lights";
    EXPECT_EQ(projected.lightCount, 0u);

    RenderSettings gmip;
    gmip.functions["RayTraversal"] = "gmip";
    EXPECT_EQ(policy.choose(gmip, offerWith(0), {}).composition.functionFor("Gradient"), "central")
        << "gmip requires a gradient";

    RenderSettings debug;
    debug.functions["Shading"] = "debug";
    const Composition debugView = policy.choose(debug, offerWith(2), {}).composition;
    EXPECT_EQ(debugView.lightCount, 2u) << "debug views see the lights (LightUse::Optional)";
    for (const Composition& c : {unlit, lit, projected, debugView}) EXPECT_EQ(policy.invalidReason(c), "") << c.key();
}

TEST(CompositionPolicy, ClipShapesGoToTheImplementationOfTheirKind)
{
    const CompositionPolicy policy;
    osg::ref_ptr<ClipBoxNode> box = new ClipBoxNode;
    osg::ref_ptr<ClipPlaneNode> plane = new ClipPlaneNode;
    osg::ref_ptr<ClipEllipsoidNode> ellipsoid = new ClipEllipsoidNode;
    // Scene order box, plane, ellipsoid: planes cut whole rays first, then the opaque depth.
    const ChosenComposition chosen = policy.choose({}, offerWith(0, {box.get(), plane.get(), ellipsoid.get()}, true), {});
    EXPECT_EQ(chosen.composition.instancesOf("ClipRay"), (std::vector<std::string>{"plane", "depth"}));
    EXPECT_EQ(chosen.composition.instancesOf("ClipPosition"), (std::vector<std::string>{"box", "ellipsoid"}));
    ASSERT_EQ(chosen.clips.at("ClipRay").size(), 2u);
    EXPECT_EQ(chosen.clips.at("ClipRay")[0].node, plane.get());
    EXPECT_EQ(chosen.clips.at("ClipRay")[1].node, nullptr) << "the depth instance has no shape";
    EXPECT_EQ(chosen.clips.at("ClipPosition")[0].node, box.get());
    EXPECT_EQ(chosen.clips.at("ClipPosition")[1].node, ellipsoid.get());

    RenderSettings perSample;
    perSample.functions["ClipRay"] = "null";
    const ChosenComposition sampled = policy.choose(perSample, offerWith(0, {box.get(), plane.get()}, true), {});
    EXPECT_TRUE(sampled.composition.instancesOf("ClipRay").empty()) << "ray clipping off: no depth either";
    EXPECT_EQ(sampled.composition.instancesOf("ClipPosition"), (std::vector<std::string>{"plane", "box"}));
    RenderSettings namedPlane;
    namedPlane.functions["ClipPosition"] = "plane";
    EXPECT_EQ(policy.choose(namedPlane, offerWith(0, {plane.get()}), {}).composition.instancesOf("ClipPosition"),
              (std::vector<std::string>{"plane"}));
    RenderSettings noClip;
    noClip.forceNull = {"ClipPosition"};
    EXPECT_TRUE(policy.choose(noClip, offerWith(0, {box.get()}), {}).composition.instancesOf("ClipPosition").empty());

    // A forced composition's instances bind the offered shapes of their kind, or none.
    Composition forced;
    forced.instances["ClipPosition"] = {"ellipsoid", "box", "mask"};
    const auto clips = policy.assignClips(forced, offerWith(0, {box.get(), plane.get(), ellipsoid.get()}));
    EXPECT_EQ(clips.at("ClipPosition")[0].node, ellipsoid.get());
    EXPECT_EQ(clips.at("ClipPosition")[1].node, box.get());
    EXPECT_EQ(clips.at("ClipPosition")[2].node, nullptr);
}

TEST(CompositionPolicy, OverlappingEmissionAbsorptionVolumesShareOneRay)
{
    const CompositionPolicy policy;
    Composition dvr, back, mip, average;
    back.choice["RayTraversal"] = "dvr_back_to_front";
    mip.choice["RayTraversal"] = "mip";
    average.choice["RayTraversal"] = "average";
    EXPECT_TRUE(policy.canShareRay(dvr));
    EXPECT_TRUE(policy.canShareRay(back));
    EXPECT_TRUE(policy.canShareRay(mip)) << "with other MIP volumes: their maxima add";
    EXPECT_FALSE(policy.canShareRay(average));
    EXPECT_EQ(policy.memberKind(dvr), "emission_absorption");
    EXPECT_EQ(policy.memberKind(mip), "maximum");
    const std::vector<osg::BoundingBoxd> bounds = {{0, 0, 0, 2, 2, 2}, {5, 5, 5, 6, 6, 6}, {1, 1, 1, 3, 3, 3}, {2.5, 2.5, 2.5, 5.5, 5.5, 5.5}};
    const auto groups = policy.rayGroups(bounds, {&dvr, &back, &dvr, &dvr}, false);
    ASSERT_EQ(groups.size(), 1u) << "overlap is transitive: 0-2, 2-3, 3-1";
    EXPECT_EQ(groups[0].members, (std::vector<std::size_t>{0, 1, 2, 3}));
    EXPECT_TRUE(groups[0].shared);
    EXPECT_FALSE(policy.rayGroups(bounds, {&dvr, &back, &mip, &dvr}, false)[0].shared) << "different kinds";
    EXPECT_FALSE(policy.rayGroups(bounds, {&dvr, &back, &average, &dvr}, false)[0].shared);
    EXPECT_TRUE(policy.rayGroups(bounds, {&mip, &mip, &mip, &mip}, false)[0].shared);
    EXPECT_FALSE(policy.rayGroups(bounds, {&dvr, &back, &dvr, &dvr}, true)[0].shared) << "forced compositions";
    const auto apart = policy.rayGroups({{0, 0, 0, 1, 1, 1}, {1, 0, 0, 2, 1, 1}}, {&dvr, &dvr}, false);
    EXPECT_EQ(apart.size(), 2u) << "touching boxes do not overlap";
}

TEST(CompositionPolicy, ASetOwnsTheRayAndTheDepthClip)
{
    const CompositionPolicy policy;
    osg::ref_ptr<ClipPlaneNode> plane = new ClipPlaneNode;
    std::vector<ChosenComposition> members = {policy.choose({}, offerWith(1, {plane.get()}, true), {}),
                                              policy.choose({}, offerWith(0, {}, true), {})};
    const ChosenComposition set = policy.setComposition(members);
    EXPECT_EQ(set.composition.functionFor("RayTraversal"), "sum_of_media");
    EXPECT_EQ(set.composition.functionFor("RaySetup"), "box_intersection");
    EXPECT_EQ(set.composition.functionFor("Jitter"), "hash");
    EXPECT_EQ(set.composition.instancesOf("ClipRay"), (std::vector<std::string>{"depth"}));
    ASSERT_EQ(set.composition.members.size(), 2u);
    EXPECT_EQ(set.composition.members[0].instancesOf("ClipRay"), (std::vector<std::string>{"plane"}));
    EXPECT_EQ(members[0].clips.at("ClipRay").size(), 1u);
    EXPECT_EQ(members[0].clips.at("ClipRay")[0].node, plane.get());
    EXPECT_TRUE(set.composition.members[1].instancesOf("ClipRay").empty());
    for (const Composition& m : set.composition.members) {
        EXPECT_EQ(m.functionFor("Jitter"), "null");
        EXPECT_EQ(m.functionFor("Acceleration"), "occupancy") << "each member skips its own medium";
        EXPECT_EQ(m.functionFor("RayTraversal"), "dvr_front_to_back");
    }
    EXPECT_EQ(set.composition.members[0].lightCount, 1u);
}

TEST(CompositionPolicy, ASetTraversalNamedForAVolumeDecidesHowItsSetCombines)
{
    // `traversal=additive` draws the volume alone as dvr and its set adds the members' images;
    // `traversal=mip` members get the set that adds maxima (their Acceleration dropped: it takes
    // no leaps); unnamed emission-absorption members combine their media.
    const CompositionPolicy policy;
    EXPECT_EQ(policy.resolve("RayTraversal", "additive"), "additive");
    EXPECT_EQ(policy.resolve("RayTraversal", "composite"), "sum_of_media");
    EXPECT_EQ(policy.resolve("RayTraversal", "mip_additive"), "mip_additive");
    const std::vector<std::string> names = policy.choosable("RayTraversal");
    EXPECT_EQ(names.front(), "dvr_front_to_back");
    EXPECT_NE(std::find(names.begin(), names.end(), "additive"), names.end());
    auto chosen = [&](const std::string& traversal) {
        RenderSettings s;
        if (!traversal.empty()) s.functions["RayTraversal"] = traversal;
        return policy.choose(s, offerWith(0), {});
    };
    const ChosenComposition additive = chosen("additive");
    EXPECT_EQ(additive.composition.functionFor("RayTraversal"), "dvr_front_to_back");
    EXPECT_EQ(additive.setTraversal, "additive");
    EXPECT_EQ(additive.composition.key(), chosen("").composition.key()) << "alone it is plain dvr";
    std::vector<ChosenComposition> images = {additive, chosen("")};
    EXPECT_EQ(policy.setComposition(images).composition.functionFor("RayTraversal"), "additive");
    std::vector<ChosenComposition> media = {chosen(""), additive};
    EXPECT_EQ(policy.setComposition(media).composition.functionFor("RayTraversal"), "sum_of_media") << "the first's";
    EXPECT_EQ(policy.setComposition(media).composition.members[0].functionFor("Acceleration"), "occupancy");
    for (const char* name : {"mip", "mip_additive"}) {
        std::vector<ChosenComposition> maxima = {chosen(name), chosen("mip")};
        EXPECT_EQ(maxima[0].composition.functionFor("RayTraversal"), "mip");
        const ChosenComposition set = policy.setComposition(maxima);
        EXPECT_EQ(set.composition.functionFor("RayTraversal"), "mip_additive") << name;
        for (const Composition& m : set.composition.members) EXPECT_EQ(m.functionFor("Acceleration"), "null");
    }
}

TEST(CompositionPolicy, EmptySpaceSkippingIsTheDefaultWhereverItCanWork)
{
    const CompositionPolicy policy;
    auto acceleration = [&](std::map<std::string, std::string> functions, std::size_t lights = 0) {
        RenderSettings s;
        s.functions = std::move(functions);
        const Composition c = policy.choose(s, offerWith(lights), {}).composition;
        EXPECT_EQ(policy.invalidReason(c), "") << c.key();
        return c.functionFor("Acceleration");
    };
    EXPECT_EQ(acceleration({}), "occupancy");
    EXPECT_EQ(acceleration({}, 2), "occupancy") << "lit";
    EXPECT_EQ(acceleration({{"RayTraversal", "dvr_back_to_front"}}), "occupancy");
    for (const char* classification : {"tf1d", "premultiplied", "threshold", "null"})
        EXPECT_EQ(acceleration({{"Classification", classification}}), "occupancy") << classification;
    for (const char* traversal : {"minip", "isosurface"})
        EXPECT_EQ(acceleration({{"RayTraversal", traversal}}), "range") << traversal << " leaps past what cannot pass its level";
    EXPECT_EQ(acceleration({{"RayTraversal", "mip"}}), "null") << "measured slower with the leaps (docs/bench/skipping.md)";
    EXPECT_EQ(acceleration({{"RayTraversal", "mip"}, {"Acceleration", "range"}}), "range") << "when asked";
    EXPECT_EQ(acceleration({{"RayTraversal", "dvr_back_to_front"}, {"Acceleration", "adaptive"}}), "adaptive") << "when asked";
    for (const char* traversal : {"average", "mida", "gmip"})
        EXPECT_EQ(acceleration({{"RayTraversal", traversal}}), "null") << traversal << " does not leap";
    EXPECT_EQ(acceleration({{"RayTraversal", "mip"}, {"Reconstruction", "null"}}), "null");
    EXPECT_EQ(acceleration({{"Reconstruction", "null"}}), "null") << "a constant fetch says nothing of the voxels";
    RenderSettings off;
    off.functions["Acceleration"] = "null";
    EXPECT_EQ(policy.choose(off, offerWith(0), {}).composition.functionFor("Acceleration"), "null");
}

TEST(CompositionPolicy, InvalidCompositionsAreRejectedWithTheirReason)
{
    const CompositionPolicy policy;
    auto reason = [&](std::map<std::string, std::string> choice, unsigned int lights = 0,
                      std::map<std::string, std::vector<std::string>> instances = {}) {
        Composition c;
        c.choice = {{"GradientInput", "null"}};  // its default is scalar, for the gradient the policy adds
        for (const auto& [slot, name] : choice) c.choice[slot] = name;
        c.lightCount = lights;
        c.instances = std::move(instances);
        return policy.invalidReason(c);
    };
    EXPECT_EQ(reason({}), "");
    EXPECT_NE(reason({{"RayTraversal", "null"}}).find("nothing marches"), std::string::npos);
    EXPECT_EQ(reason({{"RayTraversal", "null"},
                      {"Reconstruction", "null"},
                      {"VolumeStorage", "null"},
                      {"Classification", "null"},
                      {"Jitter", "null"},
                      {"Acceleration", "null"}}),
              "");
    EXPECT_NE(reason({{"GradientInput", "scalar"}}).find("nothing calls GradientInput"), std::string::npos);
    EXPECT_NE(reason({{"Shading", "lighting"}, {"Illumination", "lambert"}}).find("needs a light"), std::string::npos);
    EXPECT_NE(reason({{"Shading", "lighting"}}, 1).find("needs a real Illumination"), std::string::npos);
    EXPECT_NE(reason({{"Illumination", "lambert"}}).find("nothing calls Illumination"), std::string::npos);
    EXPECT_NE(reason({}, 1).find("uses no lights"), std::string::npos);
    EXPECT_NE(reason({{"Gradient", "central"}}).find("nothing calls Gradient"), std::string::npos);
    EXPECT_NE(reason({{"RayTraversal", "gmip"}, {"Reconstruction", "null"}, {"VolumeStorage", "null"}}).find("needs a real Gradient"),
              std::string::npos);
    EXPECT_NE(reason({{"Reconstruction", "null"}, {"VolumeStorage", "null"}, {"Acceleration", "occupancy"}})
                  .find("needs a Reconstruction bounded by its voxels"),
              std::string::npos);
    EXPECT_EQ(reason({{"Reconstruction", "null"}, {"VolumeStorage", "null"}}), "");
    EXPECT_NE(reason({{"Reconstruction", "null"}}).find("nothing calls VolumeStorage"), std::string::npos);
    EXPECT_NE(reason({{"VolumeStorage", "null"}}).find("Reconstruction/trilinear needs a real VolumeStorage"), std::string::npos);
    EXPECT_EQ(reason({{"VolumeStorage", "bricked"}, {"Reconstruction", "tricubic"}}), "");
    EXPECT_EQ(reason({{"Acceleration", "occupancy"}}), "");
    EXPECT_NE(reason({{"RayTraversal", "mip"}, {"Acceleration", "occupancy"}}).find("occupancy leaps by opacity, RayTraversal/mip by extremum"),
              std::string::npos);
    EXPECT_NE(reason({{"Acceleration", "range"}}).find("range leaps by extremum, RayTraversal/dvr_front_to_back by opacity"),
              std::string::npos);
    EXPECT_NE(reason({{"RayTraversal", "average"}, {"Acceleration", "range"}}).find("nothing calls Acceleration"), std::string::npos);
    EXPECT_NE(reason({{"RayTraversal", "sum_of_media"}}).find("only in multi-volume sets"), std::string::npos);
    EXPECT_NE(reason({{"Jitter", "sparkle"}}).find("no implementation Jitter/sparkle"), std::string::npos);
    EXPECT_NE(reason({}, 0, {{"ClipRay", {"depth", "depth"}}}).find("may appear once"), std::string::npos);
    EXPECT_NE(reason({{"RayTraversal", "mip"}, {"Shading", "debug"}}).find("nothing calls Shading"), std::string::npos);
}

TEST(CompositionPolicy, ResolvesNamesAliasesAndOnOff)
{
    const CompositionPolicy policy;
    EXPECT_EQ(policy.resolve("RayTraversal", "dvr"), "dvr_front_to_back");
    EXPECT_EQ(policy.resolve("Illumination", "Cook-Torrance"), "cook_torrance");
    EXPECT_EQ(policy.resolve("Gradient", "central-9"), "central9");
    EXPECT_EQ(policy.resolve("Jitter", "on"), "hash");
    EXPECT_EQ(policy.resolve("Gradient", "on"), "central");
    EXPECT_EQ(policy.resolve("Shading", "off"), "null");
    EXPECT_EQ(policy.resolve("ClipRay", "on"), "") << "no implementation is what 'on' means there";
    EXPECT_EQ(policy.resolve("RayTraversal", "sum_of_media"), "sum_of_media") << "a set traversal with a member traversal";
    EXPECT_EQ(policy.resolve("Jitter", "sparkle"), "");
    EXPECT_EQ(policy.choosable("Jitter").front(), "hash") << "default first";
}

/// Slot function names called in `text` (comments removed, definitions not counted).
std::set<std::string> calledSlots(std::string text)
{
    text = std::regex_replace(text, std::regex(R"(//[^\n]*)"), "");
    std::set<std::string> called;
    // Slots with a second function besides SlotInfo::function (slots.glsl).
    std::vector<std::pair<std::string, std::string>> functions = {{"VolumeStorage", "volren_volumeTexel"},
                                                                  {"Acceleration", "volren_stepsPerSample"},
                                                                  {"Shadowing", "volren_occlusion"}};
    for (const SlotInfo& s : slots())
        if (!s.function.empty()) functions.emplace_back(s.name, s.function);
    for (const auto& [slot, function] : functions) {
        const std::regex call("(\\w+\\s+)?\\b" + function + "\\s*\\(");
        for (auto it = std::sregex_iterator(text.begin(), text.end(), call); it != std::sregex_iterator(); ++it) {
            const std::string type = (*it)[1].str();
            if (std::regex_match(type, std::regex(R"((float|vec[234]|bool|void|int)\s+)"))) continue;  // a definition
            called.insert(slot);
        }
    }
    return called;
}

std::string fileText(const std::string& path)
{
    std::ifstream in(path);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

TEST(CompositionPolicy, DeclaredCallsMatchEachImplementationsSource)
{
    // The policy decides which slots are dead code from what implementations declare they call:
    // the declarations must say what the GLSL (with its includes and build program) does.
    const ShaderFunctionRegistry& registry = ShaderFunctionRegistry::instance();
    std::size_t checked = 0;
    for (const SlotInfo& s : slots())
        for (const std::string& name : registry.allNames(s.name)) {
            const ShaderFunction* f = registry.find(s.name, name);
            if (!f->traits.calls) continue;
            std::string text = fileText(registry.locate(f->file));
            for (const std::string& include : f->includes) text += fileText(registry.locate(include));
            if (!f->buildFile.empty()) text += fileText(registry.locate(f->buildFile));  // its build's calls too
            const std::set<std::string> declared(f->traits.calls->begin(), f->traits.calls->end());
            EXPECT_EQ(calledSlots(text), declared) << s.name << "/" << name;
            for (const std::string& r : f->traits.required) EXPECT_TRUE(declared.count(r)) << s.name << "/" << name << " requires " << r;
            ++checked;
        }
    EXPECT_GT(checked, 40u);
}

}  // namespace
}  // namespace volren::test
