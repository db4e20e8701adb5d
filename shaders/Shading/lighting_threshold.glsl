// Shading/lighting_threshold: lights only samples at least volren_shadingThreshold opaque
// (gradients of nearly empty samples are mostly noise); the rest keep their colour.
// vec3 volren_shade(vec3 pos, vec3 viewDir, vec4 classified)
vec3 volren_shade(vec3 pos, vec3 viewDir, vec4 classified)
{
    if (classified.a < volren_shadingThreshold) return classified.rgb;
    return volren_applyLights(pos, viewDir, classified);
}
