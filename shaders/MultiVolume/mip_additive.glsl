// MultiVolume/mip_additive: a RayTraversal of a multi-volume set whose members are drawn with
// MIP (channels of a microscopy volume, overlapping volumes): each member's maximum
// reconstructed scalar along its own interval of the ray (sampled at the midpoints of segments
// of volren_sampleDistance; clipped and NaN samples and samples of weight 0 ignored), classified
// by its own transfer function, its opacity scaled by its Weighting there (the largest where
// several samples reach it), and premultiplied
// (napari's MIP look); the images add in MultiVolume/add_images.glsl
// (volren_traverse). No leaps (members carry no Acceleration).
// vec4 volren_memberImage(int k, vec3 dir, vec3 memberOrigin, vec3 memberDir, float worldPerT, float tNear,
//                         float tFar, float jitter)
// Calls, per member k (the compositor generates these dispatchers over MultiVolume/member.glsl):
bool volren_setMemberValue(int k, vec3 pos, out float value, out float weight);
vec4 volren_setMemberClassify(int k, float value, float weight);

vec4 volren_memberImage(int k, vec3 dir, vec3 memberOrigin, vec3 memberDir, float worldPerT, float tNear, float tFar,
                        float jitter)
{
    VolrenMarch m;
    if (!(tNear < tFar) || !volren_beginMarch(dir, tNear, tFar, jitter, m)) return vec4(0.0);
    bool found = false;
    float best = -3.4e38;
    float bestWeight = 0.0;
    for (int i = 0; i < m.count; ++i) {
        float value, weight;
        if (!volren_setMemberValue(k, memberOrigin + memberDir * volren_segmentMid(m, i, tNear, tFar), value, weight))
            continue;
        if (!found || value > best) {
            best = value;
            bestWeight = weight;
            found = true;
        } else if (value == best) {  // a tie shows as its most weighted sample
            bestWeight = max(bestWeight, weight);
        }
    }
    return found ? volren_setMemberClassify(k, best, bestWeight) : vec4(0.0);
}
