// VolumeStorage/texture: the sampled level is one 3D texture (volren_volume, linear filtering,
// clamped to its edge voxels): the storage of every volume that fits the GPU's budget.
// float volren_volumeSample(vec3 pos)
// float volren_volumeTexel(ivec3 voxel)
float volren_volumeSample(vec3 pos)
{
    return texture(volren_volume, pos).r;
}

float volren_volumeTexel(ivec3 voxel)
{
    return texelFetch(volren_volume, voxel, 0).r;
}
