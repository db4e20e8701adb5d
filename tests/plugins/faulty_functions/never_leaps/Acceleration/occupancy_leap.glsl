// Acceleration/occupancy_leap, wrong on purpose (tests/plugins/faulty_functions): it reads the
// grid but never leaps, so skipping changes nothing and saves nothing; found first on
// $VOLREN_SHADER_PATH in place of the real include.
float volren_skip(vec3 origin, vec3 dir, float t, float tFar, out float tRecheck)
{
    ivec3 cell = volren_cellAt(origin, dir, t);
    int factor = int(volren_coarseFactor);
    ivec3 coarse = cell / factor;
    bool coarseEmpty = texelFetch(volren_occupancy, ivec3(int(volren_cellCount.x) + coarse.x, coarse.y, coarse.z), 0).r == 0.0;
    tRecheck = coarseEmpty ? volren_cellExit(origin, dir, t, vec3(coarse * factor), float(factor))
                           : volren_cellExit(origin, dir, t, vec3(cell), 1.0);
    return t;  // the planted fault: it never leaps
}
