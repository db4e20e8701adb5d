// Gradient/backward: one-sided differences towards -x, -y, -z (4 fetches).
// vec3 volren_gradient(vec3 pos)
vec3 volren_gradient(vec3 pos)
{
    vec3 h = 1.0 / volren_dims;
    vec3 spacing = volren_worldSize / volren_dims;
    float f = volren_gradientInput(pos);
    return vec3(f - volren_gradientInput(pos - vec3(h.x, 0.0, 0.0)),
                f - volren_gradientInput(pos - vec3(0.0, h.y, 0.0)),
                f - volren_gradientInput(pos - vec3(0.0, 0.0, h.z))) / spacing;
}
