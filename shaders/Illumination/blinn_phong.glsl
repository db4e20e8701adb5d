// Illumination/blinn_phong: Lambert diffuse plus a white Blinn-Phong highlight.
// vec3 volren_illuminate(vec3 normal, vec3 viewDir, vec3 lightDir, vec3 albedo)
vec3 volren_illuminate(vec3 normal, vec3 viewDir, vec3 lightDir, vec3 albedo)
{
    float diffuse = max(dot(normal, lightDir), 0.0);
    vec3 halfway = lightDir + viewDir;
    float len = length(halfway);
    float specular = (diffuse > 0.0 && len > 1e-6) ? pow(max(dot(normal, halfway / len), 0.0), volren_shininess) : 0.0;
    return albedo * diffuse + vec3(volren_specular * specular);
}
