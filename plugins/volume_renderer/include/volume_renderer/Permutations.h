#pragma once
#include <volume_renderer/CompositionPolicy.h>

#include <cstdint>
#include <string>
#include <vector>

namespace volren {

/// The space of valid compositions: the cross product of every slot's implementations (the
/// registry's names, in name order, so indices stay put; not the multi-volume ones), clip instances 0..maxInstances per template slot and
/// 0..maxLights lights, minus what CompositionPolicy::isValid rejects. Adding an implementation
/// to the registry grows the space; nothing here names one.
class PermutationSpace
{
public:
    PermutationSpace(const ShaderFunctionRegistry& registry, unsigned int maxInstances, unsigned int maxLights);

    /// Number of valid compositions.
    std::size_t size() const { return _valid.size(); }
    /// Valid composition `index` (0 <= index < size()).
    Composition at(std::size_t index) const;
    /// Indices of a covering subset: every pair of factor values (slot choices, clip instance
    /// lists, light counts) that occurs in some valid composition occurs in one of these.
    std::vector<std::size_t> pairwiseCover() const;
    /// The policy whose rules the space follows.
    const CompositionPolicy& policy() const { return _policy; }

private:
    struct Factor
    {
        std::string name;                 ///< slot name, "lights"
        std::vector<std::string> values;  ///< implementation names; "[a,b]" lists; counts
    };
    Composition compose(const std::vector<std::uint8_t>& choice) const;

    CompositionPolicy _policy;
    std::vector<Factor> _factors;
    std::vector<std::vector<std::uint8_t>> _valid;
};

}  // namespace volren
