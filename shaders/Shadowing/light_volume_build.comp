// Shadowing/light_volume (build): one slice of the light volume per dispatch, for one light.
// The C++ side (LightVolume.cpp) sweeps the slices along the axis most aligned with the light,
// nearest the light first, so the neighbouring slice towards the light is always complete.
// Each texel's transmittance is that neighbour's (bilinear gather at the point where the path
// to the light crosses it) times exp(-optical depth) of the path between them, integrated from
// the full-resolution volume through the composition's Reconstruction, Classification and
// ClipPosition at steps of at most volren_shadowStep (midpoints, each segment's opacity
// corrected for its length). A path that leaves the box or reaches a point light before the
// neighbouring slice starts from full light there. The only approximation is the bilinear
// gather of the stored transmittance.
// main() of a compute program; per dispatch: volren_buildLight, volren_buildAxis, volren_buildSlice.
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;
#if VOLREN_LIGHT_COUNT <= 1
layout(r16f, binding = 1) uniform image3D volren_lightImage;
#elif VOLREN_LIGHT_COUNT == 2
layout(rg16f, binding = 1) uniform image3D volren_lightImage;
#else
layout(rgba16f, binding = 1) uniform image3D volren_lightImage;
#endif
uniform int volren_buildLight;  // the light being built: channel volren_buildLight % 4 of layer volren_buildLight / 4
#if VOLREN_LIGHT_COUNT > 4
const int volren_lightLayers = 2;  // lights 4-7 in a second layer stacked along z
#else
const int volren_lightLayers = 1;
#endif
int volren_layerZ = 0;   // the built light's layer: its first z in the image
int volren_channel = 0;  // its channel there
uniform int volren_buildAxis;   // the sweep axis
uniform int volren_buildSlice;  // the slice along it

/// The texel of slice `slice` at in-plane coordinates `uv` (the two other axes, in order).
ivec3 volren_sliceTexel(int slice, ivec2 uv)
{
    if (volren_buildAxis == 0) return ivec3(slice, uv.x, uv.y);
    if (volren_buildAxis == 1) return ivec3(uv.x, slice, uv.y);
    return ivec3(uv.x, uv.y, slice);
}

/// The transmittance of light `volren_buildLight` at texture-space point q on slice `slice`:
/// bilinear over the slice's texels; between the outermost texel centres and a face the light
/// leaves the box through (dirTex points out of it there), towards 1 at the face itself, where
/// the path to the light leaves at once (clamping there instead would let a column along the
/// face read its own edge texel all the way, never leaving through the face).
float volren_gatherSlice(int slice, vec3 q, ivec3 n, vec3 dirTex)
{
    ivec2 size = volren_buildAxis == 0 ? n.yz : volren_buildAxis == 1 ? n.xz : n.xy;
    vec2 plane = volren_buildAxis == 0 ? q.yz : volren_buildAxis == 1 ? q.xz : q.xy;
    vec2 dir = volren_buildAxis == 0 ? dirTex.yz : volren_buildAxis == 1 ? dirTex.xz : dirTex.xy;
    vec2 unclamped = plane * vec2(size) - 0.5;
    vec2 st = clamp(unclamped, vec2(0.0), vec2(size - 1));
    ivec2 i0 = ivec2(floor(st));
    ivec2 i1 = min(i0 + 1, size - 1);
    vec2 f = st - vec2(i0);
    ivec3 layer = ivec3(0, 0, volren_layerZ);
    float t00 = imageLoad(volren_lightImage, layer + volren_sliceTexel(slice, i0))[volren_channel];
    float t10 = imageLoad(volren_lightImage, layer + volren_sliceTexel(slice, ivec2(i1.x, i0.y)))[volren_channel];
    float t01 = imageLoad(volren_lightImage, layer + volren_sliceTexel(slice, ivec2(i0.x, i1.y)))[volren_channel];
    float t11 = imageLoad(volren_lightImage, layer + volren_sliceTexel(slice, i1))[volren_channel];
    float t = mix(mix(t00, t10, f.x), mix(t01, t11, f.x), f.y);
    for (int b = 0; b < 2; ++b) {
        float beyond = unclamped[b] - st[b];  // in texels past the outermost centre, up to 1/2 at the face
        if ((beyond < 0.0 && dir[b] < 0.0) || (beyond > 0.0 && dir[b] > 0.0)) t = mix(t, 1.0, min(abs(beyond) * 2.0, 1.0));
    }
    return t;
}

void main()
{
    ivec3 n = imageSize(volren_lightImage);
    n.z /= volren_lightLayers;  // one layer's texels
    volren_layerZ = (volren_buildLight / 4) * n.z;
    volren_channel = volren_buildLight % 4;
    ivec3 texel = volren_sliceTexel(volren_buildSlice, ivec2(gl_GlobalInvocationID.xy));
    if (any(greaterThanEqual(texel, n))) return;
    vec3 pos = (vec3(texel) + 0.5) / vec3(n);
    vec4 light = volren_lightPosition[volren_buildLight];
    vec3 toLight = light.w == 0.0 ? light.xyz : light.xyz - (pos - 0.5) * volren_worldSize;
    float lightDistance = light.w == 0.0 ? 1e30 : length(toLight);
    float transmittance = 1.0;
    float len = length(toLight);
    if (len > 0.0 && lightDistance > 0.0) {
        vec3 dirTex = toLight / len / volren_worldSize;  // texture space per world unit
        float exitDistance = volren_boxExit(pos, dirTex);
        // The neighbouring slice towards the light, and the distance to its plane.
        float along = dirTex[volren_buildAxis];
        int neighbour = volren_buildSlice + (along > 0.0 ? 1 : -1);
        float planeDistance = abs(along) > 1e-30 ? 1.0 / (float(n[volren_buildAxis]) * abs(along)) : 1e30;
        bool fromNeighbour = neighbour >= 0 && neighbour < n[volren_buildAxis] && planeDistance <= exitDistance &&
                             planeDistance < lightDistance;
        float pathLength = fromNeighbour ? planeDistance : min(exitDistance, lightDistance);
        float incoming = fromNeighbour ? volren_gatherSlice(neighbour, pos + dirTex * planeDistance, n, dirTex) : 1.0;
        float depth = 0.0;
        if (pathLength > 0.0 && volren_shadowStep > 0.0) {
            int count = int(min(ceil(pathLength / volren_shadowStep), 4096.0));
            float h = pathLength / float(count);
            float ratio = h / volren_referenceStep;
            for (int i = 0; i < count; ++i) {
                vec3 p = pos + dirTex * ((float(i) + 0.5) * h);
                if (volren_clipPosition(p)) continue;
                depth += volren_opticalDepth(volren_classify(volren_fetchScalar(p)).a * volren_weight(p), ratio);
            }
        }
        transmittance = clamp(incoming, 0.0, 1.0) * exp(-depth);
    }
    ivec3 at = texel + ivec3(0, 0, volren_layerZ);
    vec4 stored = imageLoad(volren_lightImage, at);
    stored[volren_channel] = transmittance;
    imageStore(volren_lightImage, at, stored);
}
