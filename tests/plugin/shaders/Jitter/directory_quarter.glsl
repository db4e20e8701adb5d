// Jitter/directory_quarter (test shader folder, no C++): every ray starts a quarter step late.
// float volren_jitter(vec2 fragCoord)
float volren_jitter(vec2 fragCoord)
{
    return 0.25;
}
