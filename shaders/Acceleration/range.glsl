// Acceleration/range: skipping for MIP, MinIP and isosurfaces over the macrocells' value ranges.
// volren_cellRanges holds per cell of macrocellSize^3 voxels the smallest and largest texel
// value its samples can read (the Reconstruction's footprint included; +inf, -inf for cells of
// NaN only), and beside it along x, from texel volren_cellCount.x on, the same for coarse cells
// of volren_coarseFactor^3 cells. A (coarse) cell whose values cannot pass level (above: the
// running maximum, or the float below the iso value; else the running minimum) is left at its
// exit, one cell per pass of the traversal's own loop: the extremum or the first hit, and so the
// image, is the one without skipping.
// float volren_skip(vec3 origin, vec3 dir, float t, float tFar, float level, bool above, out float tRecheck)
// int volren_stepsPerSample(...): Acceleration/every_step.glsl
float volren_skip(vec3 origin, vec3 dir, float t, float tFar, float level, bool above, out float tRecheck)
{
    ivec3 count = ivec3(volren_cellCount);
    ivec3 cell = volren_cellAt(origin, dir, t);
    int factor = int(volren_coarseFactor);
    ivec3 coarse = cell / factor;
    vec2 coarseRange = texelFetch(volren_cellRanges, ivec3(count.x + coarse.x, coarse.y, coarse.z), 0).rg;
    bool coarseDone = above ? coarseRange.y <= level : coarseRange.x >= level;
    vec2 range = texelFetch(volren_cellRanges, cell, 0).rg;
    bool done = coarseDone || (above ? range.y <= level : range.x >= level);
    tRecheck = coarseDone ? volren_cellExit(origin, dir, t, vec3(coarse * factor), float(factor))
                          : volren_cellExit(origin, dir, t, vec3(cell), 1.0);
    return done ? tRecheck : t;
}
