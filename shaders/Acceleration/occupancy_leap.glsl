// Acceleration/occupancy_leap.glsl (included by occupancy and adaptive): TF-aware empty-space
// skipping over the macrocell occupancy grid volren_occupancy: one texel per cell (non-zero
// where a sample may be visible), and beside it along x, from texel volren_cellCount.x on, a
// coarse level: one texel per volren_coarseFactor^3 cells. In an empty coarse cell, or else an
// empty cell, the answer is the ray's exit from it, so the traversal's own loop walks the grid
// one cell per pass (a DDA without a loop of its own: with one nested in the march, llvmpipe
// stopped rays of 40,000 samples at 32,768). The cells' value ranges include the
// Reconstruction's footprint, so every sample leapt over classifies to zero opacity: the image
// is the one without skipping.
float volren_skip(vec3 origin, vec3 dir, float t, float tFar, out float tRecheck)
{
    ivec3 cell = volren_cellAt(origin, dir, t);
    int factor = int(volren_coarseFactor);
    ivec3 coarse = cell / factor;
    bool coarseEmpty = texelFetch(volren_occupancy, ivec3(int(volren_cellCount.x) + coarse.x, coarse.y, coarse.z), 0).r == 0.0;
    tRecheck = coarseEmpty ? volren_cellExit(origin, dir, t, vec3(coarse * factor), float(factor))
                           : volren_cellExit(origin, dir, t, vec3(cell), 1.0);
    return coarseEmpty || texelFetch(volren_occupancy, cell, 0).r == 0.0 ? tRecheck : t;
}
