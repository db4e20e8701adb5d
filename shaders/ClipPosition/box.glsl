// ClipPosition/box: keeps the inside of a box (its own coordinates: volren_clipMatrix maps
// texture space there); volren_clipInvert keeps the outside instead. Template instance.
// bool volren_clipPosition(vec3 pos)
bool volren_clipPosition(vec3 pos)
{
    vec3 q = (volren_clipMatrix * vec4(pos, 1.0)).xyz;
    bool inside = all(greaterThanEqual(q, volren_clipBoxMin)) && all(lessThanEqual(q, volren_clipBoxMax));
    return inside == volren_clipInvert;
}
