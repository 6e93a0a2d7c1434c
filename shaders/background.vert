// The background: one quad over the screen, turned with the panel, so
// "top" is the top of the picture as the viewer sees it. u_turn: the
// panel's rotation as a 2x2 matrix; u_scale: the share of the image
// shown on each axis (it covers the screen; 1, 1 for a gradient);
// u_slice: this screen's part of a wall, its centre and half sizes in the
// wall's NDC (0, 0, 1, 1: the whole picture), so a wall shows one
// gradient or image across its screens.

attribute vec2 a_position; // -1..1, the panel's axes

uniform vec4 u_turn; // the columns of a 2x2 matrix
uniform vec2 u_scale;
uniform vec4 u_slice;

varying vec2 v_uv;

void main()
{
	vec2 p = (u_slice.xy + a_position * u_slice.zw) * u_scale;

	v_uv = vec2(p.x * 0.5 + 0.5, 0.5 - p.y * 0.5); // rows top first
	gl_Position = vec4(mat2(u_turn.xy, u_turn.zw) * a_position, 0.0, 1.0);
}
