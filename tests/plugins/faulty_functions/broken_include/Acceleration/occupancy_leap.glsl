// Acceleration/occupancy_leap.glsl, broken on purpose (tests/plugins/faulty_functions): a copy
// of an include file with a syntax error; it overrides the include, and is no implementation.
float volren_skip(vec3 origin, vec3 dir, float t, float tFar, out float tRecheck)
{
    tRecheck = t +;
    return t;
}
