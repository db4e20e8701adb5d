// Acceleration/adaptive: empty-space skipping (Acceleration/occupancy_leap.glsl) plus adaptive
// sampling with a bound. The grid's visible cells are 1.0 where the classification (opacity and
// opacity-weighted colour) varies by at most the tolerance over every value the cell's samples
// can read (its value range with the Reconstruction's footprint), 128/255 elsewhere. In such a
// homogeneous cell one sample stands for up to volren_adaptiveSteps steps of the march, up to
// the cell's exit: no feature inside the cell can differ from it by more than the tolerance,
// however thin, because every value there is within the range. Elsewhere every step is taken.
// float volren_skip(vec3 origin, vec3 dir, float t, float tFar, out float tRecheck)
// int volren_stepsPerSample(vec3 origin, vec3 dir, float t, out float tEnd)
int volren_stepsPerSample(vec3 origin, vec3 dir, float t, out float tEnd)
{
    ivec3 cell = volren_cellAt(origin, dir, t);
    tEnd = volren_cellExit(origin, dir, t, vec3(cell), 1.0);
    return texelFetch(volren_occupancy, cell, 0).r > 0.75 ? volren_adaptiveSteps : 1;
}
