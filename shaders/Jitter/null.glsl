// Jitter/null: every ray starts a full step after its entry point.
// float volren_jitter(vec2 fragCoord)
float volren_jitter(vec2 fragCoord)
{
    return 0.0;
}
