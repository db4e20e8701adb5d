// RaySetup/null: casts no rays; the volume's box leaves the framebuffer untouched.
in vec4 volren_vClip;
out vec4 volren_fragColor;

void main()
{
    discard;
}
