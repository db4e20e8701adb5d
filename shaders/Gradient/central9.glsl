// Gradient/central9: each component is the central difference averaged over the 3x3
// neighbourhood across the other two axes (9 positions, 54 fetches): smooth on noisy data.
// vec3 volren_gradient(vec3 pos)
vec3 volren_gradient(vec3 pos)
{
    vec3 h = 1.0 / volren_dims;
    vec3 spacing = volren_worldSize / volren_dims;
    vec3 sum = vec3(0.0);
    for (int i = -1; i <= 1; ++i) {
        for (int j = -1; j <= 1; ++j) {
            vec3 ax = pos + vec3(0.0, float(i) * h.y, float(j) * h.z);
            vec3 ay = pos + vec3(float(i) * h.x, 0.0, float(j) * h.z);
            vec3 az = pos + vec3(float(i) * h.x, float(j) * h.y, 0.0);
            sum.x += volren_gradientInput(ax + vec3(h.x, 0.0, 0.0)) - volren_gradientInput(ax - vec3(h.x, 0.0, 0.0));
            sum.y += volren_gradientInput(ay + vec3(0.0, h.y, 0.0)) - volren_gradientInput(ay - vec3(0.0, h.y, 0.0));
            sum.z += volren_gradientInput(az + vec3(0.0, 0.0, h.z)) - volren_gradientInput(az - vec3(0.0, 0.0, h.z));
        }
    }
    return sum / (18.0 * spacing);
}
