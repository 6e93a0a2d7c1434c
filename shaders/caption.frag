// The caption's pixel, premultiplied: blended ONE, ONE_MINUS_SRC_ALPHA.

varying vec2 v_uv;

uniform sampler2D u_image;

void main()
{
	gl_FragColor = texture2D(u_image, v_uv);
}
