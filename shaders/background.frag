// The background's pixel: the image's, or the gradient's from top to
// bottom.

varying vec2 v_uv;

#ifdef BACKGROUND_IMAGE
uniform sampler2D u_image;
#else
uniform vec3 u_top;
uniform vec3 u_bottom;
#endif

void main()
{
#ifdef BACKGROUND_IMAGE
	gl_FragColor = vec4(texture2D(u_image, v_uv).rgb, 1.0);
#else
	gl_FragColor = vec4(mix(u_top, u_bottom, v_uv.y), 1.0);
#endif
}
