// Weighting/null: every sample keeps its opacity.
// float volren_weight(vec3 pos)
float volren_weight(vec3 pos)
{
    return 1.0;
}
