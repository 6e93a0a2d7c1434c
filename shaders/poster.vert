// The poster: one image over the screen, scaled to fit and turned with
// the panel. u_fit: the image's share of the screen on each axis (1 on
// the axis it fills); u_turn: the panel's rotation as a 2x2 matrix.

attribute vec2 a_position; // -1..1

uniform vec2 u_fit;
uniform vec4 u_turn; // the columns of a 2x2 matrix

varying vec2 v_uv;

void main()
{
	v_uv = vec2(a_position.x * 0.5 + 0.5, 0.5 - a_position.y * 0.5);
	gl_Position = vec4(mat2(u_turn.xy, u_turn.zw) * (a_position * u_fit), 0.0, 1.0);
}
