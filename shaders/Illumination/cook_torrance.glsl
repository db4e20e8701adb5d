// Illumination/cook_torrance: microfacet reflection (GGX distribution, Smith-Schlick
// geometry, Schlick Fresnel with F0 = 0.04) plus Lambert diffuse. NaN-safe: every
// denominator is bounded away from zero and grazing angles return finite values.
// vec3 volren_illuminate(vec3 normal, vec3 viewDir, vec3 lightDir, vec3 albedo)
vec3 volren_illuminate(vec3 normal, vec3 viewDir, vec3 lightDir, vec3 albedo)
{
    float nl = dot(normal, lightDir);
    if (!(nl > 0.0)) return vec3(0.0);
    float nv = max(dot(normal, viewDir), 1e-4);
    vec3 halfway = lightDir + viewDir;
    float len = length(halfway);
    vec3 h = len > 1e-6 ? halfway / len : normal;
    float nh = max(dot(normal, h), 0.0);
    float vh = max(dot(viewDir, h), 0.0);
    float a = max(volren_roughness * volren_roughness, 1e-4);
    float a2 = a * a;
    float d = nh * nh * (a2 - 1.0) + 1.0;
    float distribution = a2 / max(3.14159265 * d * d, 1e-12);
    float k = a * 0.5;
    float geometry = (nl / (nl * (1.0 - k) + k)) * (nv / (nv * (1.0 - k) + k));
    float fresnel = 0.04 + 0.96 * pow(1.0 - vh, 5.0);
    float specular = distribution * geometry * fresnel / max(4.0 * nl * nv, 1e-6);
    return albedo * nl + vec3(volren_specular * specular * nl);
}
