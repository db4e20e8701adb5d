// Weighting implementations: a factor on each sample's opacity by its position in the volume.
#include <volume_renderer/ShaderFunctionRegistry.h>

#include <volume_model/RenderSettings.h>

#include <algorithm>
#include <cctype>

namespace volren {

void registerWeightingFunctions(ShaderFunctionRegistry& registry)
{
    registry.add({.slot = "Weighting",
                  .name = "null",
                  .traits = {.calls = SlotList{}},
                  .reference = ReferenceModel::exact("unweighted")});

    // The node's curves weightX, weightY, weightZ as hinges (Weighting/axes.glsl): up to
    // WeightCurve::maxKnots - 1 (15) segments per axis, four per vec4.
    static_assert(WeightCurve::maxKnots <= 17, "Weighting/axes.glsl holds 16 segments per axis");
    ShaderFunction axes{.slot = "Weighting",
                        .name = "axes",
                        .uniforms = {{"volren_weightStart", "vec4", "12"},
                                     {"volren_weightLength", "vec4", "12"},
                                     {"volren_weightSlope", "vec4", "12"},
                                     {"volren_weightBase", "vec3", ""}},
                        .traits = {.calls = SlotList{}},
                        .reference = ReferenceModel::exact("axis curves"),
                        // The cost of the weights at every sample.
                        .benchRows = {{{"weightZ", "ramp:0.1"}}}};
    for (const char* axis : {"X", "Y", "Z"})
        axes.parameters.push_back({.key = std::string("weight") + axis, .type = ParameterType::Curve,
                                   .defaultValue = WeightCurve{},
                                   .help = std::string("opacity weight along ") + char(std::tolower(*axis)) +
                                           " over u in [0,1] of the volume (microscopy: 'ramp:0.05' fades the "
                                           "first and last 5% of the slices)",
                                   .label = std::string("weight ") + char(std::tolower(*axis)),
                                   .panel = {PanelHint::Text}});
    // Only the segments the curves have are evaluated, compiled in (a driver that runs a branch's
    // both sides pays for every segment it could have, as much as for the sample itself): per
    // axis, the vec4s of segments (four each).
    axes.defines = {{"VOLREN_WEIGHT_GROUPS_X", "0"}, {"VOLREN_WEIGHT_GROUPS_Y", "0"}, {"VOLREN_WEIGHT_GROUPS_Z", "0"}};
    axes.compileOptions = [](const CompileContext& c) {
        const SpatialWeighting weighting = spatialWeighting(c.settings);
        CompileOptions options;
        std::string groups;
        bool any = false;
        for (std::size_t axis = 0; axis < 3; ++axis) {
            const std::size_t knots = weighting.axes[axis].knots.size();
            const unsigned int n = knots > 1 ? unsigned((knots - 2) / 4 + 1) : 0u;
            options.defines[std::string("VOLREN_WEIGHT_GROUPS_") + "XYZ"[axis]] = std::to_string(n);
            groups += (axis ? "," : "") + std::to_string(n);
            any = any || n > 0;
        }
        if (any) options.keyFragment = "weightGroups=" + groups + ";";
        return options;
    };
    axes.bind = [](BindContext& c) {
        const SpatialWeighting weighting = spatialWeighting(c.settings);
        osg::Vec3f base;
        for (unsigned int axis = 0; axis < 3; ++axis) {
            const auto& knots = weighting.axes[axis].knots;
            base[axis] = knots.empty() ? 1.0f : float(knots.front().second);
            for (unsigned int quad = 0; quad < 4; ++quad) {
                osg::Vec4f start, length, slope;  // unused segments: all 0
                for (unsigned int j = 0; j < 4; ++j) {
                    const std::size_t i = 4 * quad + j;
                    if (i + 1 >= knots.size()) continue;
                    // A step (knots closer than any sample can tell) rises over 1e-6, so its slope stays finite.
                    const double du = std::max(knots[i + 1].first - knots[i].first, 1e-6);
                    start[j] = float(knots[i].first);
                    length[j] = float(du);
                    slope[j] = float((knots[i + 1].second - knots[i].second) / du);
                }
                c.uniformElement("volren_weightStart", 12, 4 * axis + quad, start);
                c.uniformElement("volren_weightLength", 12, 4 * axis + quad, length);
                c.uniformElement("volren_weightSlope", 12, 4 * axis + quad, slope);
            }
        }
        c.uniform("volren_weightBase", base);
    };
    registry.add(axes);
}

}  // namespace volren
