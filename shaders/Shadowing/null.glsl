// Shadowing/null: every light reaches every sample unoccluded.
// float volren_shadow(vec3 pos, vec3 lightDir)
float volren_shadow(vec3 pos, vec3 lightDir)
{
    return 1.0;
}
