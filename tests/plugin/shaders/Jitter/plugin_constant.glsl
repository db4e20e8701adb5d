// Jitter/plugin_constant (test plugin): every ray starts half a step late.
// float volren_jitter(vec2 fragCoord)
float volren_jitter(vec2 fragCoord)
{
    return volren_pluginJitter;
}
