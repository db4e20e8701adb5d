// RayTraversal implementations.
#include <volume_renderer/ShaderFunctionRegistry.h>

#include <volume_model/RenderSettings.h>
#include <volume_model/Volume.h>

#include <cmath>

namespace volren {

void registerRayTraversalFunctions(ShaderFunctionRegistry& registry)
{
    ShaderFunction dvr;
    dvr.slot = "RayTraversal";
    dvr.name = "dvr_front_to_back";
    dvr.file = "RayTraversal/dvr_front_to_back.glsl";
    dvr.uniforms = {{"volren_worldSize", "vec3"},
                    {"volren_sampleDistance", "float"},
                    {"volren_referenceStep", "float"},
                    {"volren_terminationDepth", "float"}};
    dvr.bind = [](BindContext& c) {
        c.uniform("volren_worldSize", osg::Vec3f(c.volume.worldSize()));
        c.uniform("volren_sampleDistance", float(c.sampleDistance));
        c.uniform("volren_referenceStep", float(c.volume.minSpacing()));
        // Opacity A reached <=> optical depth -log(1-A) reached; A = 1 never terminates early.
        const double threshold = c.settings.earlyTerminationThreshold;
        const double depth = threshold >= 1.0 ? 1e30 : -std::log1p(-threshold);
        c.uniform("volren_terminationDepth", float(depth));
    };
    registry.add(dvr);
}

}  // namespace volren
