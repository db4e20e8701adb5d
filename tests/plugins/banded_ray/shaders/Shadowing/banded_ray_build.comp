// Shadowing/banded_ray (build; a plugin's, tests/plugins/banded_ray): its auxiliary volume "band
// extinction", the classified extinction per world unit (-log(1 - alpha) over the reference
// step, at most 60000) at the centre of every voxel of the sampled level, zero where a clip shape
// removes the voxel.
// main() of a compute program; one dispatch.
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;
layout(r16f, binding = 1) uniform image3D volren_bandImage;

void main()
{
    ivec3 n = imageSize(volren_bandImage);
    ivec3 voxel = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(voxel, n))) return;
    vec3 p = (vec3(voxel) + 0.5) / vec3(n);
    float extinction = 0.0;
    if (!volren_clipPosition(p))
        extinction = min(volren_opticalDepth(volren_classify(volren_fetchScalar(p)).a * volren_weight(p), 1.0) / volren_referenceStep,
                         60000.0);
    imageStore(volren_bandImage, voxel, vec4(extinction, 0.0, 0.0, 1.0));
}
