// The scaled scene's pixel, filtered linearly between its texels.

varying vec2 v_uv;

uniform sampler2D u_image;

void main()
{
	gl_FragColor = vec4(texture2D(u_image, v_uv).rgb, 1.0);
}
