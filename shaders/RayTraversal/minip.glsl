// RayTraversal/minip: MinIP: the classified minimum of the reconstructed scalar along the ray
// (RayTraversal/extremum.glsl), its opacity scaled by the Weighting there, premultiplied.
// vec4 volren_traverse(vec3 origin, vec3 dir, float tNear, float tFar, float jitter, out float tHit)
vec4 volren_traverse(vec3 origin, vec3 dir, float tNear, float tFar, float jitter, out float tHit)
{
    tHit = -1.0;
    bool found;
    float weight;
    float best = volren_extremum(origin, dir, tNear, tFar, jitter, false, found, weight);
    if (!found) return vec4(0.0);
    vec4 c = volren_classify(best);
    c.a *= weight;  // the Weighting's factor where the extremum lies
    return vec4(c.rgb * c.a, c.a);
}
