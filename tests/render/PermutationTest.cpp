// The permutation space: validity rules, counting, and the pairwise covering subset.
#include <volume_renderer/Permutations.h>
#include <volume_renderer/Slots.h>

#include <gtest/gtest.h>

#include <map>
#include <set>
#include <cstdint>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace volren::test {
namespace {

std::map<std::string, std::string> factors(const Composition& c)
{
    std::map<std::string, std::string> f;
    const std::string key = c.key();
    std::size_t start = 0;
    while (start < key.size()) {
        const std::size_t eq = key.find('=', start), end = key.find(';', start);
        f[key.substr(start, eq - start)] = key.substr(eq + 1, end - eq - 1);
        start = end + 1;
    }
    return f;
}

TEST(Permutations, EveryCompositionIsValidAndDistinct)
{
    const PermutationSpace space(ShaderFunctionRegistry::instance(), 1, 1);
    EXPECT_GT(space.size(), 1000u);
    std::set<std::string> keys;
    for (std::size_t i = 0; i < space.size(); i += 97) {
        const Composition c = space.at(i);
        EXPECT_TRUE(CompositionPolicy().isValid(c)) << c.key();
        keys.insert(c.key());
    }
    EXPECT_EQ(keys.size(), (space.size() + 96) / 97);
}

TEST(Permutations, ValidityRulesRejectContradictions)
{
    Composition lit;
    lit.choice = {{"Shading", "lighting"}, {"Illumination", "lambert"}, {"Gradient", "central"},
                  {"GradientInput", "scalar"}};
    lit.lightCount = 1;
    EXPECT_TRUE(CompositionPolicy().isValid(lit));
    Composition noLight = lit;
    noLight.lightCount = 0;
    EXPECT_FALSE(CompositionPolicy().isValid(noLight));
    Composition halfGradient = lit;
    halfGradient.choice["GradientInput"] = "null";
    EXPECT_FALSE(CompositionPolicy().isValid(halfGradient));
    Composition mipLit = lit;
    mipLit.choice["RayTraversal"] = "mip";
    EXPECT_FALSE(CompositionPolicy().isValid(mipLit));
    Composition gmip;
    gmip.choice = {{"RayTraversal", "gmip"}, {"Gradient", "central9"}, {"GradientInput", "alpha"}, {"Acceleration", "null"}};
    EXPECT_TRUE(CompositionPolicy().isValid(gmip));
    gmip.choice["Gradient"] = "null";
    gmip.choice["GradientInput"] = "null";
    EXPECT_FALSE(CompositionPolicy().isValid(gmip));
}

TEST(Permutations, PairwiseCoverContainsEveryPairOfTheSpace)
{
    // Without clip instances (the space with one per template slot is 25 times larger, tens of
    // millions, too many to list every pair of here; `volren permutations --pairwise` covers it).
    const PermutationSpace space(ShaderFunctionRegistry::instance(), 0, 1);
    const std::vector<std::size_t> cover = space.pairwiseCover();
    EXPECT_LT(cover.size(), 200u);
    // Each "slot=implementation" factor gets a number, a pair of factors one 64-bit key: the
    // space has millions of compositions but only thousands of pairs.
    std::unordered_map<std::string, std::uint64_t> ids;
    auto pairsOf = [&](const Composition& c, std::unordered_set<std::uint64_t>& out) {
        std::vector<std::uint64_t> f;
        for (const auto& [slot, name] : factors(c)) f.push_back(ids.emplace(slot + "=" + name, ids.size()).first->second);
        for (std::size_t a = 0; a < f.size(); ++a)
            for (std::size_t b = a + 1; b < f.size(); ++b) out.insert(f[a] << 32 | f[b]);
    };
    std::unordered_set<std::uint64_t> coveredPairs, allPairs;
    for (std::size_t i : cover) pairsOf(space.at(i), coveredPairs);
    for (std::size_t i = 0; i < space.size(); ++i) pairsOf(space.at(i), allPairs);
    std::size_t missing = 0;
    for (std::uint64_t p : allPairs) missing += !coveredPairs.count(p);
    const std::size_t pairs = allPairs.size();
    EXPECT_EQ(missing, 0u) << "of " << pairs << " pairs";
    // Every implementation of every slot appears in the cover.
    for (const SlotInfo& s : slots()) {
        if (s.isTemplate) continue;
        for (const std::string& name : ShaderFunctionRegistry::instance().names(s.name)) {
            bool seen = false;
            for (std::size_t i : cover) seen = seen || space.at(i).functionFor(s.name) == name;
            EXPECT_TRUE(seen) << s.name << "/" << name;
        }
    }
}

}  // namespace
}  // namespace volren::test
