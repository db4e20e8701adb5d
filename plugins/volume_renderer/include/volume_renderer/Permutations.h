#pragma once
#include <volume_renderer/ShaderCompositor.h>

#include <cstdint>
#include <string>
#include <vector>

namespace volren {

/// The space of valid compositions: the cross product of every slot's implementations, clip
/// instances 0..maxInstances per template slot and 0..maxLights lights, minus the
/// combinations the rules below call invalid (code that could never run or contradicts itself):
/// - RaySetup null or RayTraversal null: nothing marches, so every other slot is null (two
///   compositions: box setup with null traversal, and null setup);
/// - Gradient null <=> GradientInput null; Shadowing and Acceleration only null (no others yet);
/// - a template implementation marked `single` (ClipRay depth) appears at most once;
/// - lighting shadings need a non-null Illumination and at least one light; null shading has
///   null Illumination and no lights; debug shading has null Illumination;
/// - traversals that never call Shading (MIP, MinIP, average, GMIP: ShaderFunction::calls)
///   have null Shading and Illumination and no lights; one that reads the Gradient (GMIP)
///   needs a non-null one;
/// - a Gradient is only valid where something reads it (shading other than null, or GMIP).
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
    /// Whether `c` obeys the validity rules.
    static bool isValid(const Composition& c);

private:
    struct Factor
    {
        std::string name;                 ///< slot name, "lights"
        std::vector<std::string> values;  ///< implementation names; "[a,b]" lists; counts
    };
    Composition compose(const std::vector<std::uint8_t>& choice) const;

    std::vector<Factor> _factors;
    std::vector<std::vector<std::uint8_t>> _valid;
};

}  // namespace volren
