// Shadowing/cone_march.glsl (included by cone and cone_ao): the optical depth along a cone
// through the opacity mip chain (classified extinction per world unit, box-filtered levels,
// zero outside the box). From volren_coneStart voxels out to maxDistance or the box's face,
// steps of max(volren_shadowStep, volren_coneStepGrowth x the cone's diameter there, at least a
// voxel) are sampled at their midpoints from the level whose texels span the diameter (the
// nearest level: the chain's sampler does not blend two levels, which halves the texels a step
// reads; level 0 while the diameter is below 1.5 voxels), so a narrow cone is a shadow ray
// through the extinction field and a wide one sees the pre-filtered medium around its axis.
float volren_coneDepth(vec3 pos, vec3 dirWorld, float maxDistance, float tanHalfAngle)
{
    vec3 dirTex = dirWorld / volren_worldSize;  // texture space per world unit
    float exitDistance = volren_boxExit(pos, dirTex);
    float len = min(exitDistance, maxDistance);
    float voxel = volren_coneVoxel;
    float t = volren_coneStart * voxel;
    float depth = 0.0;
    for (int i = 0; i < 4096 && t < len; ++i) {
        float diameter = max(2.0 * t * tanHalfAngle, voxel);
        float h = min(max(volren_shadowStep, volren_coneStepGrowth * diameter), len - t);
        vec3 p = pos + dirTex * (t + 0.5 * h);
        depth += textureLod(volren_opacityMips, p, log2(diameter / voxel)).r * h;
        t += h;
        if (depth >= volren_shadowCutoffDepth) break;
    }
    return depth;
}
