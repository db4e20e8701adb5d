// Shadowing/cone and cone_ao (build): the finest level of the opacity mip chain, one texel per
// voxel of the sampled level: the classified extinction per world unit at the voxel's centre
// (-log(1 - alpha) over the reference step), zero where a clip shape removes it, Gaussian
// pre-filtered over the 3 x 3 x 3 voxels around it when volren_coneFilterSigma > 0 (in voxels).
// The levels above, one dispatch each (volren_buildLevel > 0), are the mean of the 2 x 2 x 2
// texels below (an odd edge repeats its last texel).
// main() of a compute program; one dispatch per level.
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;
layout(r16f, binding = 1) uniform image3D volren_coneImage;
layout(r16f, binding = 2) uniform readonly image3D volren_coneSource;  // the level below
uniform int volren_buildLevel;

/// Classified extinction per world unit at the centre of voxel `voxel` of an image of `n`.
float volren_voxelExtinction(ivec3 voxel, ivec3 n)
{
    vec3 p = (vec3(clamp(voxel, ivec3(0), n - 1)) + 0.5) / vec3(n);
    if (volren_clipPosition(p)) return 0.0;
    return min(volren_opticalDepth(volren_classify(volren_fetchScalar(p)).a * volren_weight(p), 1.0) / volren_referenceStep, 60000.0);
}

void main()
{
    ivec3 n = imageSize(volren_coneImage);
    ivec3 voxel = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(voxel, n))) return;
    if (volren_buildLevel > 0) {
        ivec3 below = imageSize(volren_coneSource);
        float sum = 0.0;
        for (int k = 0; k < 8; ++k)
            sum += imageLoad(volren_coneSource, min(2 * voxel + ivec3(k & 1, (k >> 1) & 1, k >> 2), below - 1)).r;
        imageStore(volren_coneImage, voxel, vec4(0.125 * sum, 0.0, 0.0, 1.0));
        return;
    }
    float extinction = 0.0;
    if (volren_coneFilterSigma > 0.0) {
        float total = 0.0;
        for (int z = -1; z <= 1; ++z)
            for (int y = -1; y <= 1; ++y)
                for (int x = -1; x <= 1; ++x) {
                    ivec3 at = voxel + ivec3(x, y, z);
                    if (any(lessThan(at, ivec3(0))) || any(greaterThanEqual(at, n))) continue;
                    float w = exp(-float(x * x + y * y + z * z) / (2.0 * volren_coneFilterSigma * volren_coneFilterSigma));
                    extinction += w * volren_voxelExtinction(at, n);
                    total += w;
                }
        extinction /= total;
    } else {
        extinction = volren_voxelExtinction(voxel, n);
    }
    imageStore(volren_coneImage, voxel, vec4(extinction, 0.0, 0.0, 1.0));
}
