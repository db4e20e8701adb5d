// Reconstruction/trilinear: hardware trilinear filtering of the volume texture, at the mip level
// the node samples (volren_lod, 0 without level of detail).
// float volren_fetchScalar(vec3 pos)
float volren_fetchScalar(vec3 pos)
{
    return textureLod(volren_volume, pos, volren_lod).r;
}
