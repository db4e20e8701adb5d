// Classification/draws_nothing (a planted fault, tests/plugins/faulty_functions): transparent.
// vec4 volren_classify(float scalar)
vec4 volren_classify(float scalar)
{
    return vec4(0.0);
}
