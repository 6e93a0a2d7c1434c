// One vertex shader for every mode; the program is compiled with exactly
// one of MODE_NORMAL, MODE_VIEW, MODE_SEM_VERTEX, MODE_SEM_FRAGMENT, and
// CAMERA_ORTHO when the projection is orthographic.

attribute vec3 a_position;
attribute vec3 a_normal;

uniform mat4 u_modelview;
uniform mat4 u_projection;
uniform mat3 u_normal_matrix;

#ifdef MODE_SEM_VERTEX
varying vec2 v_uv;
#else
varying vec3 v_normal;
varying vec3 v_eye;
#endif

void main()
{
	vec4 p = u_modelview * vec4(a_position, 1.0);
	vec3 n = u_normal_matrix * a_normal;
#ifdef CAMERA_ORTHO
	vec3 eye = vec3(0.0, 0.0, -1.0);
#else
	vec3 eye = p.xyz;
#endif
#ifdef MODE_SEM_VERTEX
	v_uv = matcap_sem(safe_normalize(n), safe_normalize(eye));
#else
	v_normal = n;
	v_eye = eye;
#endif
	gl_Position = u_projection * p;
}
