// ClipPosition/plane: keeps the side of a plane its normal points to, sample by sample
// (ClipRay/plane does the same by shortening the ray); volren_clipInvert flips it.
// bool volren_clipPosition(vec3 pos)
bool volren_clipPosition(vec3 pos)
{
    bool inside = dot(volren_clipPlane.xyz, pos) + volren_clipPlane.w >= 0.0;
    return inside == volren_clipInvert;
}
