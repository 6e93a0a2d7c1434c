// The poster's pixel, as the image has it.

varying vec2 v_uv;

uniform sampler2D u_image;

void main()
{
	gl_FragColor = vec4(texture2D(u_image, v_uv).rgb, 1.0);
}
