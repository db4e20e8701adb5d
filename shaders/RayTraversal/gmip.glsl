// RayTraversal/gmip: gradient-magnitude MIP. The largest gradient magnitude along the ray,
// as a fraction of volren_gradientScale (a jump across the whole value window within one
// smallest voxel spacing), is looked up in the TF window like a scalar: strong edges take
// the colour of the window's top.
// vec4 volren_traverse(vec3 origin, vec3 dir, float tNear, float tFar, float jitter, out float tHit)
vec4 volren_traverse(vec3 origin, vec3 dir, float tNear, float tFar, float jitter, out float tHit)
{
    tHit = -1.0;
    VolrenMarch m;
    if (!volren_beginMarch(dir, tNear, tFar, jitter, m)) return vec4(0.0);
    float best = 0.0;
    for (int i = 0; i < m.count; ++i) {
        float segStart = volren_segmentStart(m, i, tNear, tFar);
        float segEnd = volren_segmentEnd(m, i, tFar);
        vec3 p = origin + dir * (0.5 * (segStart + segEnd));
        if (segEnd > segStart && !volren_clipPosition(p)) {
            float m = length(volren_gradient(p));
            if (m > best) best = m;
        }
    }
    float u = clamp(best / max(volren_gradientScale, 1e-30), 0.0, 1.0);
    vec4 c = volren_classify((u - volren_window.y) / volren_window.z / volren_window.x);  // u as a windowed scalar
    return vec4(c.rgb * c.a, c.a);
}
