// Shading/lighting: every sample lit by ambient + the scene's lights.
// vec3 volren_shade(vec3 pos, vec3 viewDir, vec4 classified)
vec3 volren_shade(vec3 pos, vec3 viewDir, vec4 classified)
{
    return volren_applyLights(pos, viewDir, classified);
}
