// RayTraversal/mida: maximum intensity difference accumulation (Bruckner & Groeller 2009):
// DVR whose accumulated colour is attenuated wherever a new maximum of the windowed scalar
// appears, so bright structures show through like MIP while keeping DVR's depth cues.
// vec4 volren_traverse(vec3 origin, vec3 dir, float tNear, float tFar, float jitter, out float tHit)
vec4 volren_traverse(vec3 origin, vec3 dir, float tNear, float tFar, float jitter, out float tHit)
{
    tHit = -1.0;
    VolrenMarch m;
    if (!volren_beginMarch(dir, tNear, tFar, jitter, m)) return vec4(0.0);
    vec3 viewDir = -normalize(dir * volren_worldSize);
    vec4 acc = vec4(0.0);
    float maximum = 0.0;
    for (int i = 0; i < m.count; ++i) {
        float segStart = volren_segmentStart(m, i, tNear, tFar);
        float segEnd = volren_segmentEnd(m, i, tFar);
        float lenT = segEnd - segStart;
        vec3 p = origin + dir * (0.5 * (segStart + segEnd));
        if (lenT > 0.0 && !volren_clipPosition(p)) {
            float s = volren_fetchScalar(p);
            if (!isnan(s)) {
                float u = clamp(s * volren_window.x * volren_window.z + volren_window.y, 0.0, 1.0);
                float delta = u > maximum ? u - maximum : 0.0;
                maximum = max(maximum, u);
                float beta = 1.0 - delta;
                vec4 c = volren_classify(s);
                float a = volren_opacityFromDepth(volren_opticalDepth(c.a, lenT * m.worldPerT / volren_referenceStep));
                vec3 rgb = volren_shade(p, viewDir, c);
                acc.rgb = beta * acc.rgb + (1.0 - beta * acc.a) * a * rgb;
                acc.a = beta * acc.a + (1.0 - beta * acc.a) * a;
                if (acc.a >= volren_terminationOpacity && maximum >= 1.0) break;  // nothing can change any more
            }
        }
    }
    return acc;
}
