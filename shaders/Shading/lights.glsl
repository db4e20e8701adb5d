// Shading/lights.glsl (included by the lighting shadings): ambient (scaled by the Shadowing's
// ambient occlusion) plus the sum over the scene's lights of Illumination x Shadowing. Light positions are in the node's local
// coordinates (w = 0: direction towards the light, w = 1: point light).
vec3 volren_applyLights(vec3 pos, vec3 viewDir, vec4 classified)
{
    vec3 local = (pos - 0.5) * volren_worldSize;
    vec3 normal = volren_normalFromGradient(volren_gradient(pos), viewDir);
    vec3 colour = volren_ambient * volren_occlusion(pos, normal) * classified.rgb;
    for (int i = 0; i < VOLREN_LIGHT_COUNT; ++i) {
        vec4 light = volren_lightPosition[i];
        vec3 toLight = light.w == 0.0 ? light.xyz : light.xyz - local;
        float len = length(toLight);
        if (!(len > 0.0)) continue;
        vec3 lightDir = toLight / len;
        colour += volren_lightColour[i] * volren_shadow(pos, lightDir, light.w == 0.0 ? 1e30 : len, i) *
                  volren_illuminate(normal, viewDir, lightDir, classified.rgb);
    }
    return colour;
}
