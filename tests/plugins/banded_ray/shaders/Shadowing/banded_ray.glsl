// Shadowing/banded_ray (a plugin's, tests/plugins/banded_ray): the light reaching a sample through
// its own volume, marched in volren_bandCount equal segments from the sample to where the light's
// path leaves the box (or reaches a point light), however long that path is: each segment's
// optical depth is its length times the extinction read (trilinear) at its midpoint from the
// auxiliary volume volren_bandExtinction (built by banded_ray_build.comp; clipped-away voxels hold
// none). Opaque geometry is not looked at.
// float volren_shadow(vec3 pos, vec3 lightDir, float lightDistance, int light)
float volren_shadow(vec3 pos, vec3 lightDir, float lightDistance, int light)
{
    vec3 dirTex = lightDir / volren_worldSize;  // texture space per world unit
    float len = min(volren_boxExit(pos, dirTex), lightDistance);
    if (!(len > 0.0)) return 1.0;
    float h = len / float(volren_bandCount);
    float depth = 0.0;
    for (int i = 0; i < volren_bandCount; ++i)
        depth += texture(volren_bandExtinction, pos + dirTex * ((float(i) + 0.5) * h)).r * h;
    return exp(-depth);
}

// No ambient occlusion.
float volren_occlusion(vec3 pos, vec3 normal)
{
    return 1.0;
}
