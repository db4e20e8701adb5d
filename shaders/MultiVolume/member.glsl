// MultiVolume/member: one member of a multi-volume set, compiled once per member after its own
// slot implementations; the compositor renames every volren_ name in a member's code with the
// member's suffix _v<k> (volren_memberRay becomes volren_memberRay_v0, volren_volume becomes
// volren_volume_v0, ...), so the members' slots, uniforms and textures are kept apart. Names the
// set program defines once (common/numerics.glsl, RaySetup/ray.glsl) are shared, not renamed.
// Every function defined here whose name starts volren_member gets a dispatcher over the members,
// volren_setMember... with the member's index k first (ProgramAssembly::appendMembers), which the
// set traversals call.
// void volren_memberRay(vec3 origin, vec3 dir, out vec3 memberOrigin, out vec3 memberDir,
//                       out float worldPerT, inout float tNear, inout float tFar)
// float volren_memberSample(vec3 pos, vec3 memberDir, float worldLength, out vec3 emitted)
// float volren_memberSkip(vec3 memberOrigin, vec3 memberDir, float t, float tFar, out float tRecheck)
// bool volren_memberValue(vec3 pos, out float value, out float weight)
// vec4 volren_memberClassify(float value, float weight)

// The set's ray in this member's texture space (volren_setToMember: set box -> member texture
// space), its world length per unit t in the member's local units, and [tNear, tFar] narrowed to
// the member's box and clip planes.
void volren_memberRay(vec3 origin, vec3 dir, out vec3 memberOrigin, out vec3 memberDir,
                      out float worldPerT, inout float tNear, inout float tFar)
{
    memberOrigin = (volren_setToMember * vec4(origin, 1.0)).xyz;
    memberDir = mat3(volren_setToMember) * dir;
    worldPerT = length(memberDir * volren_worldSize);
    float boxNear, boxFar;
    volren_boxInterval(memberOrigin, memberDir, boxNear, boxFar);  // the set's (RaySetup/ray.glsl)
    tNear = max(tNear, boxNear);
    tFar = min(tFar, boxFar);
    volren_clipRay(memberOrigin, memberDir, tNear, tFar);
}

// Optical depth of this member's medium over a segment of worldLength (member-local units)
// around pos, and its shaded colour there (emitted); zero where clipped or empty.
float volren_memberSample(vec3 pos, vec3 memberDir, float worldLength, out vec3 emitted)
{
    emitted = vec3(0.0);
    if (volren_clipPosition(pos)) return 0.0;
    vec4 c = volren_classify(volren_fetchScalar(pos));
    c.a *= volren_weight(pos);
    float dTau = volren_opticalDepth(c.a, worldLength / volren_referenceStep);
    if (dTau > 0.0) emitted = volren_shade(pos, -normalize(memberDir * volren_worldSize), c);
    return dTau;
}

// This member's empty-space skipping along its ray (its own Acceleration): no sample of it in
// [t, returned) may be visible; the answer holds up to tRecheck.
float volren_memberSkip(vec3 memberOrigin, vec3 memberDir, float t, float tFar, out float tRecheck)
{
    return volren_skip(memberOrigin, memberDir, t, tFar, tRecheck);
}

// This member's reconstructed scalar at pos and its Weighting there; false where it does not
// count (clipped, NaN, or of weight 0).
bool volren_memberValue(vec3 pos, out float value, out float weight)
{
    value = 0.0;
    weight = volren_clipPosition(pos) ? 0.0 : volren_weight(pos);
    if (!(weight > 0.0)) return false;
    value = volren_fetchScalar(pos);
    return !isnan(value);
}

// This member's classification of `value`, its opacity scaled by `weight`, premultiplied (unlit,
// as the projections show it).
vec4 volren_memberClassify(float value, float weight)
{
    vec4 c = volren_classify(value);
    c.a *= weight;
    return vec4(c.rgb * c.a, c.a);
}
