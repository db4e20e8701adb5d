// Shadowing/null: every light reaches every sample unoccluded.
// float volren_shadow(vec3 pos, vec3 lightDir, float lightDistance, int light)
float volren_shadow(vec3 pos, vec3 lightDir, float lightDistance, int light)
{
    return 1.0;
}

// No ambient occlusion.
float volren_occlusion(vec3 pos, vec3 normal)
{
    return 1.0;
}
