#pragma once
#include <map>
#include <string>
#include <vector>

namespace volren {

/// What the scene asks of the ray caster: one implementation per ordinary slot, a list of
/// instances per template slot, and the number of lights. Made by the CompositionPolicy.
struct Composition
{
    std::map<std::string, std::string> choice;                  ///< slot -> implementation
    std::map<std::string, std::vector<std::string>> instances;  ///< template slot -> one per shape
    unsigned int lightCount = 0;                                ///< lights the shading loops over
    /// Compile-time options the chosen implementations' hooks set for this scene (macro name ->
    /// value; ShaderFunction::compileOptions); a macro not here has its declared default.
    std::map<std::string, std::string> defines;
    /// The hooks' key fragments, in slot order: they tell every value of `defines` apart.
    std::string keyFragments;
    /// A multi-volume set: one composition per member (their sample slots, clip planes and
    /// lights), marched along one ray by this composition's RayTraversal (`sum_of_media`).
    std::vector<Composition> members;

    /// Full key "Slot=impl;...;ClipPosition=[box,plane];lights=N;" plus the key fragments over
    /// every slot, defaults filled in; programs are cached by the whole key.
    std::string key() const;
    /// Implementation for ordinary `slot` (CompositionPolicy::defaultImplementation when not chosen).
    std::string functionFor(const std::string& slot) const;
    /// The instances of template `slot` (none when not listed).
    const std::vector<std::string>& instancesOf(const std::string& slot) const;
};

}  // namespace volren
