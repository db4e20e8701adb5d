// Acceleration/null: no empty-space skipping and no adaptive steps; every step is sampled
// (asked once per ray).
// float volren_skip(vec3 origin, vec3 dir, float t, float tFar, out float tRecheck)
// float volren_skip(vec3 origin, vec3 dir, float t, float tFar, float level, bool above, out float tRecheck)
// int volren_stepsPerSample(...): Acceleration/every_step.glsl
float volren_skip(vec3 origin, vec3 dir, float t, float tFar, out float tRecheck)
{
    tRecheck = 1e30;
    return t;
}

float volren_skip(vec3 origin, vec3 dir, float t, float tFar, float level, bool above, out float tRecheck)
{
    tRecheck = 1e30;
    return t;
}
