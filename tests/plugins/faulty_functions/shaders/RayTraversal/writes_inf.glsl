// RayTraversal/writes_inf (a planted fault, tests/plugins/faulty_functions): every ray returns
// +Inf (NaN would not reach the framebuffer: RaySetup/ray.glsl turns a NaN colour transparent).
// vec4 volren_traverse(vec3 origin, vec3 dir, float tNear, float tFar, float jitter, out float tHit)
vec4 volren_traverse(vec3 origin, vec3 dir, float tNear, float tFar, float jitter, out float tHit)
{
    tHit = -1.0;
    return vec4(uintBitsToFloat(0x7f800000u));
}
