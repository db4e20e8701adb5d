// Shading/debug: shows one intermediate quantity as colour (volren_debugView):
// 0 scalar, 1 position, 2 classification, 3 gradient, 4 normal, 5 view direction,
// 6 direction to the first light. Vectors map [-1,1] to [0,1].
// vec3 volren_shade(vec3 pos, vec3 viewDir, vec4 classified)
vec3 volren_shade(vec3 pos, vec3 viewDir, vec4 classified)
{
    if (volren_debugView == 0) return vec3(volren_fetchScalar(pos));
    if (volren_debugView == 1) return pos;
    if (volren_debugView == 2) return classified.rgb;
    vec3 g = volren_gradient(pos);
    if (volren_debugView == 3) return clamp(g / max(volren_gradientScale, 1e-30), -1.0, 1.0) * 0.5 + 0.5;
    if (volren_debugView == 4) return volren_normalFromGradient(g, viewDir) * 0.5 + 0.5;
    if (volren_debugView == 5) return viewDir * 0.5 + 0.5;
    if (VOLREN_LIGHT_COUNT == 0) return vec3(0.0);
    vec4 light = volren_lightPosition[0];
    vec3 toLight = light.w == 0.0 ? light.xyz : light.xyz - (pos - 0.5) * volren_worldSize;
    return (length(toLight) > 0.0 ? normalize(toLight) : vec3(0.0)) * 0.5 + 0.5;
}
