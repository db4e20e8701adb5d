// Acceleration/every_step.glsl (included by the Accelerations without adaptive steps: null,
// occupancy, range): every step of the march is sampled, and the answer never needs asking again.
int volren_stepsPerSample(vec3 origin, vec3 dir, float t, out float tEnd)
{
    tEnd = 1e30;
    return 1;
}
