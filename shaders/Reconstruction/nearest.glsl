// Reconstruction/nearest: the value of the voxel whose cell contains pos (volren_dims: the
// voxels of the volume texture, the mip level the node samples).
// float volren_fetchScalar(vec3 pos)
float volren_fetchScalar(vec3 pos)
{
#ifdef VOLREN_COUNT_SAMPLES
    ++volren_sampleCount;
#endif
    ivec3 size = ivec3(volren_dims);
    ivec3 voxel = clamp(ivec3(floor(pos * volren_dims)), ivec3(0), size - 1);
    return volren_volumeTexel(voxel);
}
