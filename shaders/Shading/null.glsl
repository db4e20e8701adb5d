// Shading/null: the classified colour is emitted unlit.
// vec3 volren_shade(vec3 pos, vec3 viewDir, vec4 classified)
vec3 volren_shade(vec3 pos, vec3 viewDir, vec4 classified)
{
    return classified.rgb;
}
