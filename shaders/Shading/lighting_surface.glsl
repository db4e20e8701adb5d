// Shading/lighting_surface: lit on boundaries, emissive inside homogeneous material (surface
// enhancement by gradient magnitude): the lit colour weighted by w = 1 - exp(-|g| / (0.05 G)),
// the unlit TF colour by 1 - w, where G = volren_gradientScale is the gradient of a jump across
// the whole TF window within one voxel (a jump of 5% of the window per voxel gives w = 0.63).
// Where the gradient is zero nothing is lit, so noise-free interiors keep their colour exactly.
// vec3 volren_shade(vec3 pos, vec3 viewDir, vec4 classified)
vec3 volren_shade(vec3 pos, vec3 viewDir, vec4 classified)
{
    float magnitude = length(volren_gradient(pos));
    float w = -volren_expm1(-magnitude / max(0.05 * volren_gradientScale, 1e-30));
    if (!(w > 0.0)) return classified.rgb;
    return mix(classified.rgb, volren_applyLights(pos, viewDir, classified), w);
}
