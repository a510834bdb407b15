// Method `zexel`: a warped zexel's colour and its distance from the mirrored eye (the frame's
// alpha convention, which the mirror turns into the reflected ray's length).
in vec4 v_color;

layout(location = 0) out vec4 out_color;
layout(location = 1) out uint out_id;

void main() {
  out_color = v_color;
  out_id = 0u;
}
