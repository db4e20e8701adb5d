// Acceleration/occupancy: TF-aware empty-space skipping over the macrocell occupancy grid
// (Acceleration/occupancy_leap.glsl); every visible sample is taken (no adaptive steps).
// float volren_skip(vec3 origin, vec3 dir, float t, float tFar, out float tRecheck)
// int volren_stepsPerSample(vec3 origin, vec3 dir, float t, out float tEnd)
int volren_stepsPerSample(vec3 origin, vec3 dir, float t, out float tEnd)
{
    tEnd = 1e30;
    return 1;
}
