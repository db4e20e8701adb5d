// Gradient/central: central differences over one voxel each way (6 fetches).
// vec3 volren_gradient(vec3 pos)
vec3 volren_gradient(vec3 pos)
{
    vec3 h = 1.0 / volren_dims;
    vec3 spacing = volren_worldSize / volren_dims;
    return vec3(volren_gradientInput(pos + vec3(h.x, 0.0, 0.0)) - volren_gradientInput(pos - vec3(h.x, 0.0, 0.0)),
                volren_gradientInput(pos + vec3(0.0, h.y, 0.0)) - volren_gradientInput(pos - vec3(0.0, h.y, 0.0)),
                volren_gradientInput(pos + vec3(0.0, 0.0, h.z)) - volren_gradientInput(pos - vec3(0.0, 0.0, h.z))) /
           (2.0 * spacing);
}
