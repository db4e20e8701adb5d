// Shadowing/geometry_shadow.glsl (included by every shadowing method): whether the scene's opaque
// geometry lets light `light` reach texture-space point `pos`, from the depth map of that
// geometry seen from the light (one layer per light; the 2x2 texels around the point compared
// and mixed bilinearly, in the shader: core profiles may not set a texture's compare mode).
// volren_geometryShadowMatrix[light] maps texture space to the map's [0,1]^3 coordinates (a
// zero matrix: no map covers this light); volren_geometryShadowCount is the number of maps.
// Points outside the map are lit. Without opaque geometry (VOLREN_GEOMETRY_SHADOWS 0, from
// the Shadowing's compile options) the lookup is compiled out.
// float volren_geometryLight(vec3 pos, int light)
float volren_geometryLight(vec3 pos, int light)
{
#if !VOLREN_GEOMETRY_SHADOWS
    return 1.0;
#else
    if (light >= volren_geometryShadowCount) return 1.0;
    vec4 p = volren_geometryShadowMatrix[light] * vec4(pos, 1.0);
    if (!(p.w > 0.0)) return 1.0;
    vec3 q = p.xyz / p.w;
    if (any(lessThan(q, vec3(0.0))) || any(greaterThan(q, vec3(1.0)))) return 1.0;
    // The 2x2 texels around the point, each compared (1: the point is not behind the geometry),
    // mixed bilinearly (the border reads 1: lit).
    vec2 size = vec2(textureSize(volren_geometryShadow, 0).xy);
    vec2 t = q.xy * size - 0.5;
    vec2 f = fract(t);
    vec4 depth = textureGather(volren_geometryShadow, vec3((floor(t) + 1.0) / size, float(light)));
    vec4 lit = step(vec4(q.z - volren_geometryShadowBias[light]), depth);  // gather: (0,1) (1,1) (1,0) (0,0)
    return mix(mix(lit.w, lit.z, f.x), mix(lit.x, lit.y, f.x), f.y);
#endif
}
