// RaySetup/null: casts no rays; the volume's box leaves the framebuffer untouched.
out vec4 volren_fragColor;

void main()
{
    discard;
}
