// Illumination/schlick: single scattering in the medium, no surface, with Schlick's approximation
// of the Henyey-Greenstein phase function (Blasi, Le Saec and Schlick 1993): k = 1.55 g - 0.55 g^3
// from the anisotropy g, (1 - k^2) / (1 - k cos)^2 where cos is between the light's travel
// (-lightDir) and viewDir; scaled by 4 pi like henyey_greenstein, so that g = 0 gives the albedo.
// vec3 volren_illuminate(vec3 normal, vec3 viewDir, vec3 lightDir, vec3 albedo)
vec3 volren_illuminate(vec3 normal, vec3 viewDir, vec3 lightDir, vec3 albedo)
{
    float g = volren_anisotropy;
    float k = 1.55 * g - 0.55 * g * g * g;
    float denominator = max(1.0 - k * dot(-lightDir, viewDir), 1e-6);
    return albedo * ((1.0 - k * k) / (denominator * denominator));
}
