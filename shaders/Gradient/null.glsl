// Gradient/null: no gradient; normals fall back to the view direction.
// vec3 volren_gradient(vec3 pos)
vec3 volren_gradient(vec3 pos)
{
    return vec3(0.0);
}
