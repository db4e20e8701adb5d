// Reconstruction/trilinear: hardware trilinear filtering of the volume texture (the texture of
// the mip level the node samples, with level of detail).
// float volren_fetchScalar(vec3 pos)
float volren_fetchScalar(vec3 pos)
{
    return texture(volren_volume, pos).r;
}
