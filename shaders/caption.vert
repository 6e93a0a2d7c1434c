// The caption: one quad in the turned screen's pixels, then the panel's
// quarter turn. u_rect: its top-left corner and size in clip units of
// the turned screen; u_turn: the rotation as a 2x2 matrix.

attribute vec2 a_position; // 0..1 across the caption, top-left first

uniform vec4 u_rect;
uniform vec4 u_turn; // the columns of a 2x2 matrix

varying vec2 v_uv;

void main()
{
	v_uv = a_position;
	gl_Position = vec4(mat2(u_turn.xy, u_turn.zw) * (u_rect.xy + a_position * u_rect.zw), 0.0,
			   1.0);
}
