// A hotspot's disc: one quad about the point's projection. u_centre: the
// point in clip units (xy) and its depth pulled towards the eye (z), so
// the depth test against the model's own depth hides a point behind it.
// u_size: the disc's radius in clip units of the framebuffer's axes;
// u_turn: the panel's quarter turn (the badge's digit stays upright).

attribute vec2 a_position; // -1..1 across the disc

uniform vec3 u_centre;
uniform vec2 u_size;
uniform vec4 u_turn; // the columns of a 2x2 matrix

varying vec2 v_at;

void main()
{
	v_at = a_position;
	gl_Position = vec4(u_centre.xy + (mat2(u_turn.xy, u_turn.zw) * a_position) * u_size,
			   u_centre.z, 1.0);
}
