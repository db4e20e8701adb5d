// Acceleration/null: no empty-space skipping; every step is sampled.
// float volren_skip(vec3 origin, vec3 dir, float t, float tFar)
float volren_skip(vec3 origin, vec3 dir, float t, float tFar)
{
    return t;
}
