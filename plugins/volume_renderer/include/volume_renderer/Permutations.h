#pragma once
#include <volume_renderer/CompositionPolicy.h>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace volren {

/// The space of valid compositions: the cross product of every slot's implementations (the
/// registry's names, in name order, so indices stay put; not the multi-volume ones), clip
/// instances 0..maxInstances per template slot and 0..maxLights lights, minus what
/// CompositionPolicy::isValid rejects. Adding an implementation to the registry grows the space;
/// nothing here names one. Compositions are decoded from their index on demand; the space holds
/// about 4 bytes per valid composition (168 MB for 41.9 million).
class PermutationSpace
{
public:
    PermutationSpace(const ShaderFunctionRegistry& registry, unsigned int maxInstances, unsigned int maxLights);

    /// Number of valid compositions.
    std::size_t size() const { return _size; }
    /// Valid composition `index` (0 <= index < size()).
    Composition at(std::size_t index) const;
    /// Whether a factor's value may be taken, given the factor's name and what the value names:
    /// the implementation of an ordinary slot ({"trilinear"}), the instances of a template slot
    /// ({"box", "plane"}; none for no instance), the light count ({"1"}).
    using ValueFilter = std::function<bool(const std::string& factor, const std::vector<std::string>& names)>;
    /// Indices of a covering subset: every pair of factor values (slot choices, clip instance
    /// lists, light counts) that occurs in some valid composition occurs in one of these. With
    /// `allowed`, of the compositions whose every value it allows (their pairs covered).
    std::vector<std::size_t> pairwiseCover(const ValueFilter& allowed = {}) const;
    /// The policy whose rules the space follows.
    const CompositionPolicy& policy() const { return _policy; }

private:
    struct Factor
    {
        std::string name;                 ///< slot name, "lights"
        std::vector<std::string> values;  ///< implementation names; "[a,b]" lists; counts
    };
    /// Valid compositions by index, compactly: each is its rank in the cross product (a mixed-
    /// radix number over the factors' value indices, the first factor fastest), held as an
    /// offset from its block's first rank. A segment holds the valid compositions of one light
    /// count and one RaySetup (the two most significant factors), in rank order.
    struct Block
    {
        std::size_t first = 0;    ///< index (within its segment) of its first composition
        std::uint64_t base = 0;   ///< rank of its first composition
    };
    struct Segment
    {
        std::size_t first = 0;  ///< index of its first composition in the space
        std::vector<Block> blocks;
        std::vector<std::uint32_t> offsets;  ///< rank - block base, per composition
    };
    Composition compose(const std::vector<std::uint8_t>& choice) const;
    /// The rank of valid composition `index`.
    std::uint64_t rank(std::size_t index) const;
    /// The factor value indices of the composition of `rank`.
    std::vector<std::uint8_t> choiceOf(std::uint64_t rank) const;

    CompositionPolicy _policy;
    std::vector<Factor> _factors;
    std::vector<Segment> _segments;  ///< in index order
    std::size_t _size = 0;
};

}  // namespace volren
