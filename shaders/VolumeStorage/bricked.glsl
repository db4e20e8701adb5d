// VolumeStorage/bricked: the mip levels' voxels in bricks of volren_brickSize^3 voxels, each with
// a one-voxel border (so linear filtering inside a brick is seamless), kept in the pool texture
// volren_brickPool (slots of volren_brickSize + 2 texels; volren_poolSize texels in all). The
// page table volren_pageTable (RGBA32F, texelFetch) holds one entry per brick of every level,
// level L's at z from volren_pageTableZ[L]: w = 1 resident at slot xyz, w = 2 constant value x,
// w = 0 missing. A sample reads the node's level (volren_firstLevel) or, where that brick is
// missing, the finest coarser level that has it; the coarsest level is always complete.
// float volren_volumeSample(vec3 pos)
// float volren_volumeTexel(ivec3 voxel)

// The page entry of the brick of `level` that holds pos, and pos in that brick's voxels.
vec4 volren_pageEntry(int level, vec3 pos, out vec3 local)
{
    vec3 dims = volren_levelDims[level];
    vec3 v = clamp(pos * dims, vec3(0.5), dims - 0.5);  // clamped to the edge voxels' centres
    ivec3 brick = min(ivec3(v / volren_brickSize), ivec3(volren_brickCounts[level]) - 1);
    local = v - vec3(brick) * volren_brickSize;
    return texelFetch(volren_pageTable, brick + ivec3(0, 0, int(volren_pageTableZ[level])), 0);
}

float volren_volumeSample(vec3 pos)
{
    for (int level = volren_firstLevel; level < volren_levelCount; ++level) {
        vec3 local;
        vec4 e = volren_pageEntry(level, pos, local);
        if (e.w == 1.0)
            return texture(volren_brickPool, (e.xyz * (volren_brickSize + 2.0) + 1.0 + local) / volren_poolSize).r;
        if (e.w == 2.0) return e.x;
    }
    return 0.0;  // not reached: the coarsest level is complete
}

float volren_volumeTexel(ivec3 voxel)
{
    vec3 pos = (vec3(voxel) + 0.5) / volren_levelDims[volren_firstLevel];
    for (int level = volren_firstLevel; level < volren_levelCount; ++level) {
        vec3 local;
        vec4 e = volren_pageEntry(level, pos, local);
        if (e.w == 1.0) return texelFetch(volren_brickPool, ivec3(e.xyz) * (int(volren_brickSize) + 2) + 1 + ivec3(local), 0).r;
        if (e.w == 2.0) return e.x;
    }
    return 0.0;
}
