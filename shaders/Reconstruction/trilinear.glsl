// Reconstruction/trilinear: hardware trilinear filtering of the voxels of the mip level the node
// samples (level of detail), wherever the VolumeStorage keeps them.
// float volren_fetchScalar(vec3 pos)
float volren_fetchScalar(vec3 pos)
{
#ifdef VOLREN_COUNT_SAMPLES
    ++volren_sampleCount;
#endif
    return volren_volumeSample(pos);
}
