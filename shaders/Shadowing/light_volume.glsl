// Shadowing/light_volume: the transmittance from each light to the sample, read (trilinear) from
// the propagated light volume: one channel per light, four per layer (lights 4-7 in a second
// layer stacked along z, each layer's z clamped to its texel centres as an edge clamps), built
// on the GPU by Shadowing/light_volume_build.comp whenever the light, the TF, the volume or a
// clip shape changes, times what the opaque geometry lets through (Shadowing/geometry_shadow.glsl).
// float volren_shadow(vec3 pos, vec3 lightDir, float lightDistance, int light)
float volren_shadow(vec3 pos, vec3 lightDir, float lightDistance, int light)
{
    float geometry = volren_geometryLight(pos, light);
#if VOLREN_LIGHT_COUNT > 4
    float nz = 0.5 * float(textureSize(volren_lightVolume, 0).z);
    int layer = light / 4;
    vec3 at = vec3(pos.xy, (clamp(pos.z * nz, 0.5, nz - 0.5) + float(layer) * nz) / (2.0 * nz));
    return clamp(texture(volren_lightVolume, at)[light - 4 * layer], 0.0, 1.0) * geometry;
#else
    return clamp(texture(volren_lightVolume, pos)[light], 0.0, 1.0) * geometry;
#endif
}

// No ambient occlusion.
float volren_occlusion(vec3 pos, vec3 normal)
{
    return 1.0;
}
