// ClipPosition/ellipsoid: keeps the inside of an axis-aligned ellipsoid of its own
// coordinates; volren_clipInvert keeps the outside. Template instance.
// bool volren_clipPosition(vec3 pos)
bool volren_clipPosition(vec3 pos)
{
    vec3 d = ((volren_clipMatrix * vec4(pos, 1.0)).xyz - volren_clipCentre) / volren_clipRadii;
    bool inside = dot(d, d) <= 1.0;
    return inside == volren_clipInvert;
}
