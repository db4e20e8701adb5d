// ClipPosition/mask: keeps where a mask volume reaches volren_clipThreshold (data units);
// volren_clipMatrix maps texture space to the mask's texture space; outside it nothing is kept.
// bool volren_clipPosition(vec3 pos)
bool volren_clipPosition(vec3 pos)
{
    vec3 m = (volren_clipMatrix * vec4(pos, 1.0)).xyz;
    bool within = all(greaterThanEqual(m, vec3(0.0))) && all(lessThanEqual(m, vec3(1.0)));
    float value = texture(volren_clipMask, m).r * volren_clipMaskValue.x + volren_clipMaskValue.y;
    bool inside = within && value >= volren_clipThreshold;
    return inside == volren_clipInvert;
}
