// The camera pass: one square over the matcap texture. Its first row
// (t = 0) is the top of the ball's circle in the camera frame, as an
// image's top row is for the image matcaps.

attribute vec2 a_position; // -1..1

// xy: where the square's first corner is in the frame (0..1 of the
// picture, before any stride padding), zw: its size (negative width:
// mirrored). From camera_crop_make().
uniform vec4 u_crop;

varying vec2 v_uv;

void main()
{
	v_uv = u_crop.xy + (a_position * 0.5 + 0.5) * u_crop.zw;
	gl_Position = vec4(a_position, 0.0, 1.0);
}
