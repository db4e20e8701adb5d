// VolumeStorage/null: no voxels (every value 0); chosen only where nothing reconstructs.
// float volren_volumeSample(vec3 pos)
// float volren_volumeTexel(ivec3 voxel)
float volren_volumeSample(vec3 pos)
{
    return 0.0;
}

float volren_volumeTexel(ivec3 voxel)
{
    return 0.0;
}
