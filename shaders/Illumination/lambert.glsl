// Illumination/lambert: ideal diffuse reflection.
// vec3 volren_illuminate(vec3 normal, vec3 viewDir, vec3 lightDir, vec3 albedo)
vec3 volren_illuminate(vec3 normal, vec3 viewDir, vec3 lightDir, vec3 albedo)
{
    return albedo * max(dot(normal, lightDir), 0.0);
}
