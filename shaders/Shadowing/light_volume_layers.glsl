// Shadowing/light_volume_layers.glsl (included by light_volume, and spliced into
// shadowed_geometry.frag): light `light`'s transmittance in a light volume of `layers` layers
// stacked along z (lights 0-3 in the first, 4-7 in the second), trilinear at texture-space `pos`;
// with two layers z is clamped to the layer's texel centres, as an edge clamp clamps one layer.
// float volren_lightVolumeAt(sampler3D lightVolume, vec3 pos, int light, int layers)
float volren_lightVolumeAt(sampler3D lightVolume, vec3 pos, int light, int layers)
{
    if (layers == 1) return clamp(texture(lightVolume, pos)[light], 0.0, 1.0);
    float nz = float(textureSize(lightVolume, 0).z) / float(layers);
    int layer = light / 4;
    vec3 at = vec3(pos.xy, (clamp(pos.z * nz, 0.5, nz - 0.5) + float(layer) * nz) / (float(layers) * nz));
    return clamp(texture(lightVolume, at)[light - 4 * layer], 0.0, 1.0);
}
