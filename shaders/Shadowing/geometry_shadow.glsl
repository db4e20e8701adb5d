// Shadowing/geometry_shadow.glsl (included by every shadowing method): whether the scene's opaque
// geometry lets light `light` reach texture-space point `pos`, from the depth map of that
// geometry seen from the light (one layer per light, compared in hardware with a 2x2 filter).
// volren_geometryShadowMatrix[light] maps texture space to the map's [0,1]^3 coordinates (a
// zero matrix: no map covers this light); volren_geometryShadowCount is 0 in scenes without
// opaque geometry, where no map is read. Points outside the map are lit.
// float volren_geometryLight(vec3 pos, int light)
float volren_geometryLight(vec3 pos, int light)
{
    if (light >= volren_geometryShadowCount) return 1.0;
    vec4 p = volren_geometryShadowMatrix[light] * vec4(pos, 1.0);
    if (!(p.w > 0.0)) return 1.0;
    vec3 q = p.xyz / p.w;
    if (any(lessThan(q, vec3(0.0))) || any(greaterThan(q, vec3(1.0)))) return 1.0;
    return texture(volren_geometryShadow, vec4(q.xy, float(light), q.z - volren_geometryShadowBias[light]));
}
