// Shadowing/cone_ao: the soft shadows of Shadowing/cone, and directional ambient occlusion: the
// cosine-weighted mean transmittance of five cones of 60 degrees aperture over the hemisphere
// around the normal (one along it, four tilted 45 degrees), each out to volren_aoDistance world
// units.
// float volren_shadow(vec3 pos, vec3 lightDir, float lightDistance, int light)
// float volren_occlusion(vec3 pos, vec3 normal)
float volren_shadow(vec3 pos, vec3 lightDir, float lightDistance, int light)
{
    return exp(-volren_coneDepth(pos, lightDir, lightDistance, tan(0.5 * volren_coneAngle))) *
           volren_geometryLight(pos, light);
}

float volren_occlusion(vec3 pos, vec3 normal)
{
    // An orthonormal frame around the normal (any tangent will do: the cones are symmetric).
    vec3 helper = abs(normal.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0);
    vec3 u = normalize(cross(normal, helper));
    vec3 v = cross(normal, u);
    const float tanHalf = 0.57735027;  // tan(30 degrees)
    const float tilt = 0.70710678;     // cos = sin of 45 degrees
    float open = exp(-volren_coneDepth(pos, normal, volren_aoDistance, tanHalf));
    float weight = 1.0;
    for (int k = 0; k < 4; ++k) {
        vec3 side = (k == 0 ? u : k == 1 ? -u : k == 2 ? v : -v);
        open += tilt * exp(-volren_coneDepth(pos, normal * tilt + side * tilt, volren_aoDistance, tanHalf));
        weight += tilt;
    }
    return open / weight;
}
