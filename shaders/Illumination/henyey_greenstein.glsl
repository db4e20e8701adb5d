// Illumination/henyey_greenstein: single scattering in the medium, no surface: the light from
// lightDir scattered towards viewDir by the Henyey-Greenstein phase function of anisotropy
// volren_anisotropy (g > 0 forward, g < 0 backward), scaled by 4 pi so that g = 0 (isotropic)
// gives the albedo itself: the sample emits its TF colour times the light that reaches it.
// vec3 volren_illuminate(vec3 normal, vec3 viewDir, vec3 lightDir, vec3 albedo)
vec3 volren_illuminate(vec3 normal, vec3 viewDir, vec3 lightDir, vec3 albedo)
{
    float g = volren_anisotropy;
    float cosTheta = dot(-lightDir, viewDir);  // light travels along -lightDir, leaves along viewDir
    float denominator = max(1.0 + g * g - 2.0 * g * cosTheta, 1e-12);
    return albedo * ((1.0 - g * g) / (denominator * sqrt(denominator)));
}
