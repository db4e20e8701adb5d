// Every implementation of the slots the reference models (Shading, Illumination, Shadowing,
// Weighting) declares how the reference models it: a model the reference implements (exactly, or
// approximately with a bound), or none with the reason; the reference picks its models by them.
#include <volume_reference/ReferenceScene.h>
#include <volume_renderer/ShaderFunctionRegistry.h>

#include <volume_model/ReferenceModel.h>

#include <gtest/gtest.h>

#include <algorithm>

namespace volren::test {
namespace {

TEST(ReferenceModels, EveryImplementationOfAModelledSlotDeclaresAModelTheReferenceImplements)
{
    const ShaderFunctionRegistry& registry = ShaderFunctionRegistry::instance();
    int declared = 0;
    for (const auto& [slot, known] : ReferenceScene::models()) {
        ASSERT_FALSE(registry.names(slot).empty()) << slot;
        for (const std::string& name : registry.names(slot)) {
            const ShaderFunction* f = registry.find(slot, name);
            ASSERT_TRUE(f->reference) << slot << "/" << name << " declares no reference model";
            EXPECT_EQ(ReferenceModelCatalog::instance().find(slot, name), &ReferenceModelCatalog::instance().all().at({slot, name}));
            const ReferenceModel& m = *f->reference;
            ++declared;
            if (m.fidelity == ReferenceModel::Fidelity::None) {
                EXPECT_FALSE(m.why.empty()) << slot << "/" << name << ": no model needs a reason";
                continue;
            }
            EXPECT_NE(std::find(known.begin(), known.end(), m.model), known.end())
                << slot << "/" << name << " declares '" << m.model << "', which the reference does not implement";
            if (m.fidelity == ReferenceModel::Fidelity::Approximate) {
                EXPECT_GT(m.bound, 0.0) << slot << "/" << name << ": an approximation states its bound";
            }
        }
    }
    EXPECT_GE(declared, 17);
    // The reference's own names are not the renderer's: it is told the model, never the implementation.
    for (const auto& [slot, known] : ReferenceScene::models())
        for (const std::string& model : known) EXPECT_EQ(registry.find(slot, model), nullptr) << slot << " " << model;
}

}  // namespace
}  // namespace volren::test
