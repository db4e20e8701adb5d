// Illumination/null: reflects nothing.
// vec3 volren_illuminate(vec3 normal, vec3 viewDir, vec3 lightDir, vec3 albedo)
vec3 volren_illuminate(vec3 normal, vec3 viewDir, vec3 lightDir, vec3 albedo)
{
    return vec3(0.0);
}
