// Reconstruction/trilinear: hardware trilinear filtering of the volume texture.
// float volren_fetchScalar(vec3 pos)
float volren_fetchScalar(vec3 pos)
{
    return texture(volren_volume, pos).r;
}
