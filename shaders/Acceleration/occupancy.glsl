// Acceleration/occupancy: TF-aware empty-space skipping over the macrocell occupancy grid
// (volren_occupancy: one texel per cell of macrocellSize^3 voxels, non-zero where a sample may
// be visible; cell c spans texture coordinates [c, c+1) / volren_cellScale). In an empty cell
// the answer is the ray's exit from that cell, so the traversal's own loop walks the grid one
// cell per pass (a 3D DDA without a loop of its own: llvmpipe's loop limiter counts nested
// loops' passes against the outer one). The cells' value ranges include the Reconstruction's
// footprint, so every sample leapt over classifies to zero opacity: the image is the one
// without skipping.
// float volren_skip(vec3 origin, vec3 dir, float t, float tFar, out float tRecheck)
float volren_skip(vec3 origin, vec3 dir, float t, float tFar, out float tRecheck)
{
    ivec3 cell = clamp(ivec3(floor((origin + dir * t) * volren_cellScale)), ivec3(0), ivec3(volren_cellCount) - 1);
    // Where the ray leaves the cell: the nearest of the three planes it moves towards.
    vec3 planes = (vec3(cell) + step(vec3(0.0), dir)) / volren_cellScale;
    vec3 tPlanes = mix(vec3(1e30), (planes - origin) / dir, notEqual(dir, vec3(0.0)));
    tRecheck = max(t, min(tPlanes.x, min(tPlanes.y, tPlanes.z)));
    return texelFetch(volren_occupancy, cell, 0).r > 0.0 ? t : tRecheck;
}
