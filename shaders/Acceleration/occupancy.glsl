// Acceleration/occupancy: TF-aware empty-space skipping over the macrocell occupancy grid.
// volren_occupancy holds one texel per cell of macrocellSize^3 voxels (non-zero where a sample
// may be visible; cell c spans texture coordinates [c, c+1) / volren_cellScale), and beside it
// along x, from texel volren_cellCount.x on, a coarse level: one texel per volren_coarseFactor^3
// cells. In an empty coarse cell, or else an empty cell, the answer is the ray's exit from it,
// so the traversal's own loop walks the grid one cell per pass (a DDA without a loop of its
// own: with one nested in the march, llvmpipe stopped rays of 40,000 samples at 32,768). The cells'
// value ranges include the Reconstruction's footprint, so every sample leapt over classifies to
// zero opacity: the image is the one without skipping.
// float volren_skip(vec3 origin, vec3 dir, float t, float tFar, out float tRecheck)
float volren_skip(vec3 origin, vec3 dir, float t, float tFar, out float tRecheck)
{
    ivec3 count = ivec3(volren_cellCount);
    ivec3 cell = clamp(ivec3(floor((origin + dir * t) * volren_cellScale)), ivec3(0), count - 1);
    int factor = int(volren_coarseFactor);
    ivec3 coarse = cell / factor;
    bool coarseEmpty = texelFetch(volren_occupancy, ivec3(count.x + coarse.x, coarse.y, coarse.z), 0).r == 0.0;
    // Where the ray leaves the (coarse) cell: the nearest of the three planes it moves towards.
    float size = coarseEmpty ? float(factor) : 1.0;
    vec3 lower = coarseEmpty ? vec3(coarse * factor) : vec3(cell);
    vec3 planes = (lower + step(vec3(0.0), dir) * size) / volren_cellScale;
    vec3 tPlanes = mix(vec3(1e30), (planes - origin) / dir, notEqual(dir, vec3(0.0)));
    tRecheck = max(t, min(tPlanes.x, min(tPlanes.y, tPlanes.z)));
    return coarseEmpty || texelFetch(volren_occupancy, cell, 0).r == 0.0 ? tRecheck : t;
}
