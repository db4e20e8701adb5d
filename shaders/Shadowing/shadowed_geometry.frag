#version 430 core
// Shadowing/light_volume on the opaque geometry: the transmittance from each opaque pixel's
// surface point to each light through the volume, read from the light volume where the way to
// the light leaves the box towards the point (1 where it misses the box, or a point light lies
// between the point and the box; see transmittanceFrom for the face). The output multiplies the pixel's colour (blending
// GL_ZERO, GL_SRC_COLOR; alpha kept) by the mean over the lights: exact for one light without
// ambient or emission, an approximation otherwise (the pass cannot separate the polygons'
// light by light). Lights past the eighth, which the light volume does not hold, count as 1.
uniform sampler2D volren_depthTexture;
uniform vec2 volren_viewportOrigin;
uniform sampler3D volren_lightVolume;
uniform int volren_lightLayers;   // layers of the light volume stacked along z (lights 0-3, 4-7)
uniform int volren_heldLights;    // lights in the light volume (<= 8)
uniform int volren_totalLights;   // lights reaching the volume
uniform vec4 volren_textureLights[8];  // texture space: w = 0 direction towards the light, w = 1 position
flat in mat4 volren_clipToTexture;
out vec4 volren_fragColour;
// Shadowing/light_volume_layers.glsl is spliced in here (ShadowedGeometry.cpp): volren_lightVolumeAt.

// Parameter range [t0, t1] of p + t d inside the unit box (t0 > t1: it misses).
vec2 unitBoxSpan(vec3 p, vec3 d)
{
    vec2 span = vec2(-1e30, 1e30);
    for (int a = 0; a < 3; ++a) {
        if (abs(d[a]) < 1e-12) {
            if (p[a] < 0.0 || p[a] > 1.0) return vec2(1.0, 0.0);
            continue;
        }
        float u = (0.0 - p[a]) / d[a], v = (1.0 - p[a]) / d[a];
        span = vec2(max(span.x, min(u, v)), min(span.y, max(u, v)));
    }
    return span;
}

// Light `light`'s transmittance at `q`, where the way towards it along `d` stays in the box
// over the parameter length `inside`. The texels hold it at their centres, half a texel in from
// the faces: at a face the light has crossed that half texel more, so there (`onFace`) it is
// extrapolated from the texel centres half a texel and 1.5 texels along the way, exactly for a
// homogeneous medium (log-linear).
float transmittanceFrom(vec3 q, vec3 d, float inside, int light, bool onFace)
{
    vec3 size = vec3(textureSize(volren_lightVolume, 0)) / vec3(1.0, 1.0, float(volren_lightLayers));  // one layer's
    float texel = 1.0 / length(d * size);  // parameter per texel
    if (!onFace || inside < 1.5 * texel) return volren_lightVolumeAt(volren_lightVolume, q, light, volren_lightLayers);
    float a = volren_lightVolumeAt(volren_lightVolume, q + d * (0.5 * texel), light, volren_lightLayers);
    float b = volren_lightVolumeAt(volren_lightVolume, q + d * (1.5 * texel), light, volren_lightLayers);
    if (a <= 0.0 || b <= 0.0) return a;
    return a * sqrt(min(a / b, 1.0));
}

void main()
{
    ivec2 pixel = ivec2(gl_FragCoord.xy - volren_viewportOrigin);
    float depth = texelFetch(volren_depthTexture, pixel, 0).r;
    if (depth >= 1.0) discard;  // no geometry here
    vec2 ndc = (vec2(pixel) + 0.5) / vec2(textureSize(volren_depthTexture, 0)) * 2.0 - 1.0;
    vec4 h = volren_clipToTexture * vec4(ndc, 2.0 * depth - 1.0, 1.0);
    vec3 p = h.xyz / h.w;
    float sum = float(volren_totalLights - volren_heldLights);
    for (int i = 0; i < volren_heldLights; ++i) {
        vec4 light = volren_textureLights[i];
        vec3 d = light.w == 0.0 ? light.xyz : light.xyz - p;
        float reach = light.w == 0.0 ? 1e30 : 1.0;  // d spans the way to a point light
        vec2 span = unitBoxSpan(p, d);
        float enter = max(span.x, 0.0);
        if (span.y <= enter || enter >= reach) {
            sum += 1.0;
            continue;
        }
        sum += transmittanceFrom(p + d * enter, d, span.y - enter, i, enter > 0.0);
    }
    volren_fragColour = vec4(vec3(sum / float(max(volren_totalLights, 1))), 1.0);
}
