// Shadowing/light_volume: the transmittance from each light to the sample, read (trilinear) from
// the propagated light volume: one channel per light (up to four), built on the GPU by
// Shadowing/light_volume_build.comp whenever the light, the TF, the volume or a clip shape
// changes. Lights beyond the fourth are unshadowed.
// float volren_shadow(vec3 pos, vec3 lightDir, float lightDistance, int light)
float volren_shadow(vec3 pos, vec3 lightDir, float lightDistance, int light)
{
    if (light > 3) return 1.0;
    return clamp(texture(volren_lightVolume, pos)[light], 0.0, 1.0);
}

// No ambient occlusion.
float volren_occlusion(vec3 pos, vec3 normal)
{
    return 1.0;
}
