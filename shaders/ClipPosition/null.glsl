// ClipPosition/null: no sample is clipped.
// bool volren_clipPosition(vec3 pos)
bool volren_clipPosition(vec3 pos)
{
    return false;
}
