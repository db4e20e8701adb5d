// Reconstruction/null: no data; every position reads 0.
// float volren_fetchScalar(vec3 pos)
float volren_fetchScalar(vec3 pos)
{
    return 0.0;
}
