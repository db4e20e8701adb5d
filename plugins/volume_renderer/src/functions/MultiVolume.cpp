// Multi-volume set functions: the set's traversal and the per-member glue. They exist only in
// the program of a set of overlapping volumes (ShaderCompositor, Composition::members).
#include "CommonBindings.h"

#include <volume_renderer/ShaderFunctionRegistry.h>

#include <volume_model/RenderSettings.h>

#include <cmath>

namespace volren {

using bindings::operator+;

void registerMultiVolumeFunctions(ShaderFunctionRegistry& registry)
{
    // The set's traversal: bound once for the set, with the set's box, the finest member step
    // (BindContext::sampleDistance) and the strictest member's early termination (settings).
    ShaderFunction sum;
    sum.slot = "RayTraversal";
    sum.name = "sum_of_media";
    sum.file = "MultiVolume/sum_of_media.glsl";
    sum.includes = {"RayTraversal/march.glsl"};
    sum.uniforms = bindings::geometry + std::vector<UniformDecl>{{"volren_sampleDistance", "float", ""},
                                                                 {"volren_terminationDepth", "float", ""}};
    sum.bind = [](BindContext& c) {
        bindings::bindGeometry(c);
        c.uniform("volren_sampleDistance", float(c.sampleDistance));
        const double threshold = c.settings.earlyTerminationThreshold;
        c.uniform("volren_terminationDepth", float(threshold >= 1.0 ? 1e30 : -std::log1p(-threshold)));
    };
    sum.multiVolume = true;
    registry.add(sum);

    // Each member's ray and sample over its own slots; bound once per member.
    ShaderFunction member;
    member.slot = "MultiVolume";
    member.name = "member";
    member.file = "MultiVolume/member.glsl";
    member.uniforms = {{"volren_setToMember", "mat4", ""}};
    member.bind = [](BindContext& c) { c.uniform("volren_setToMember", osg::Matrixf(c.setToMember)); };
    member.multiVolume = true;
    registry.add(member);
}

}  // namespace volren
