// Gradient/central, broken on purpose (tests/plugins/faulty_functions): a syntax error, found
// first on $VOLREN_SHADER_PATH in place of the real file.
// vec3 volren_gradient(vec3 pos)
vec3 volren_gradient(vec3 pos)
{
    return vec3(0.0) +;
}
