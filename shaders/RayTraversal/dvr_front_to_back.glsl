// RayTraversal/dvr_front_to_back: emission-absorption compositing, front to back, with early
// termination once the accumulated opacity reaches the threshold.
// vec4 volren_traverse(vec3 origin, vec3 dir, float tNear, float tFar, float jitter)
// Segments tile [tNear, tFar] exactly (the first shortened by the jitter, the last by the exit)
// and are sampled at their midpoints, so a homogeneous medium gives exp(-sigma*L) at any step.
// Optical depth is summed with Kahan compensation; transmittance is exp(-depth).
vec4 volren_traverse(vec3 origin, vec3 dir, float tNear, float tFar, float jitter)
{
    float worldPerT = length(dir * volren_worldSize);
    if (!(worldPerT > 0.0)) return vec4(0.0);
    float stepT = volren_sampleDistance / worldPerT;
    vec3 viewDir = -normalize(dir * volren_worldSize);
    float firstEnd = tNear + (1.0 - jitter) * stepT;
    int count = int(ceil(max(tFar - firstEnd, 0.0) / stepT)) + 1;

    precise float depth = 0.0;
    precise float compensation = 0.0;
    vec3 color = vec3(0.0);
    float segStart = tNear;
    for (int i = 0; i < count; ++i) {
        float segEnd = (i == count - 1) ? tFar : min(firstEnd + float(i) * stepT, tFar);
        float lenT = segEnd - segStart;
        if (lenT > 0.0) {
            vec3 p = origin + dir * (0.5 * (segStart + segEnd));
            if (!volren_clipPosition(p)) {
                vec4 c = volren_classify(volren_fetchScalar(p));
                float dTau = volren_opticalDepth(c.a, lenT * worldPerT / volren_referenceStep);
                if (dTau > 0.0) {
                    color += exp(-depth) * volren_opacityFromDepth(dTau) * volren_shade(p, viewDir, c);
                    precise float y = dTau - compensation;
                    precise float t = depth + y;
                    compensation = (t - depth) - y;
                    depth = t;
                    if (depth >= volren_terminationDepth) break;
                }
            }
        }
        segStart = segEnd;
    }
    return vec4(color, volren_opacityFromDepth(depth));
}
