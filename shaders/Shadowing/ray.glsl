// Shadowing/ray: a secondary march from the sample towards the light through the same volume's
// classified medium, to where it leaves the box or reaches a point light. Segments of at most
// volren_shadowStep world units tile that path exactly and are sampled at their midpoints (a
// homogeneous medium gives exp(-sigma*L) at any step); the optical depth of each is corrected
// for its length like the view ray's. Clipped-away samples (every clip shape is per sample when
// this shadowing is chosen) cast no shadow. The march stops once the transmittance falls below
// volren_shadowCutoff, returning what it has reached. Opaque geometry between the sample and the
// light stops the light (Shadowing/geometry_shadow.glsl).
// float volren_shadow(vec3 pos, vec3 lightDir, float lightDistance, int light)
float volren_shadow(vec3 pos, vec3 lightDir, float lightDistance, int light)
{
    vec3 dirTex = lightDir / volren_worldSize;  // texture space per world unit
    float exitDistance = volren_boxExit(pos, dirTex);
    float len = min(exitDistance, lightDistance);
    if (!(len > 0.0) || !(volren_shadowStep > 0.0)) return volren_geometryLight(pos, light);
    int count = int(min(ceil(len / volren_shadowStep), 16384.0));
    float h = len / float(count);
    float ratio = h / volren_referenceStep;
    float depth = 0.0;
    for (int i = 0; i < count; ++i) {
        vec3 p = pos + dirTex * ((float(i) + 0.5) * h);
        if (volren_clipPosition(p)) continue;
        depth += volren_opticalDepth(volren_classify(volren_fetchScalar(p)).a * volren_weight(p), ratio);
        if (depth >= volren_shadowCutoffDepth) break;
    }
    return exp(-depth) * volren_geometryLight(pos, light);
}

// No ambient occlusion.
float volren_occlusion(vec3 pos, vec3 normal)
{
    return 1.0;
}
