// Shadowing/null: every light reaches every sample unoccluded.
// float volren_shadow(vec3 pos, vec3 lightDir, float lightDistance)
float volren_shadow(vec3 pos, vec3 lightDir, float lightDistance)
{
    return 1.0;
}
