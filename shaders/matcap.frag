// The matcap lookup. The default float precision (mediump unless the build
// asks otherwise) is set in the header that src/shader.c puts before this.

#ifdef MODE_SEM_VERTEX
varying vec2 v_uv;
#else
varying vec3 v_normal;
varying vec3 v_eye;
#endif

uniform sampler2D u_matcap;

void main()
{
#if defined(MODE_SEM_VERTEX)
	vec2 uv = v_uv;
#else
	vec3 n = safe_normalize(v_normal);
#if defined(MODE_NORMAL)
	vec2 uv = matcap_normal(n);
#elif defined(MODE_VIEW)
	vec2 uv = matcap_view(n, safe_normalize(v_eye));
#else
	vec2 uv = matcap_sem(n, safe_normalize(v_eye));
#endif
#endif
	gl_FragColor = vec4(texture2D(u_matcap, uv).rgb, 1.0);
}
