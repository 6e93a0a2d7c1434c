// render_scale's pass: the scaled scene over the whole frame. The
// framebuffer's texture has GL's origin (bottom left), as the frame does.

attribute vec2 a_position; // -1..1

varying vec2 v_uv;

void main()
{
	v_uv = a_position * 0.5 + 0.5;
	gl_Position = vec4(a_position, 0.0, 1.0);
}
