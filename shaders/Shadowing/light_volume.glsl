// Shadowing/light_volume: the transmittance from each light to the sample, read (trilinear) from
// the propagated light volume: one channel per light (up to four), built on the GPU by
// Shadowing/light_volume_build.comp whenever the light, the TF, the volume or a clip shape
// changes, times what the opaque geometry lets through (Shadowing/geometry_shadow.glsl). Lights
// beyond the fourth are shadowed by the geometry only.
// float volren_shadow(vec3 pos, vec3 lightDir, float lightDistance, int light)
float volren_shadow(vec3 pos, vec3 lightDir, float lightDistance, int light)
{
    float geometry = volren_geometryLight(pos, light);
    if (light > 3) return geometry;
    return clamp(texture(volren_lightVolume, pos)[light], 0.0, 1.0) * geometry;
}

// No ambient occlusion.
float volren_occlusion(vec3 pos, vec3 normal)
{
    return 1.0;
}
