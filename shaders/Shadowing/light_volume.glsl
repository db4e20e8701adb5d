// Shadowing/light_volume: the transmittance from each light to the sample, read (trilinear) from
// the propagated light volume: one channel per light, four per layer (lights 4-7 in a second
// layer stacked along z; Shadowing/light_volume_layers.glsl), built on the GPU by
// Shadowing/light_volume_build.comp whenever the light, the TF, the volume or a clip shape
// changes, times what the opaque geometry lets through (Shadowing/geometry_shadow.glsl).
// float volren_shadow(vec3 pos, vec3 lightDir, float lightDistance, int light)
float volren_shadow(vec3 pos, vec3 lightDir, float lightDistance, int light)
{
    return volren_lightVolumeAt(volren_lightVolume, pos, light, VOLREN_LIGHT_COUNT > 4 ? 2 : 1) *
           volren_geometryLight(pos, light);
}

// No ambient occlusion.
float volren_occlusion(vec3 pos, vec3 normal)
{
    return 1.0;
}
