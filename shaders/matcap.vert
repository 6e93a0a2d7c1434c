// One vertex shader for every mode; the program is compiled with exactly
// one of MODE_NORMAL, MODE_VIEW, MODE_SEM_VERTEX, MODE_SEM_FRAGMENT, and
// CAMERA_ORTHO when the projection is orthographic. DETAIL_MAP and
// DETAIL_NORMAL add the UV and the tangent frame, and only then; BASE_COLOR
// the vertex colour, BASE_MAP the UV through the base map's transform.

attribute vec3 a_position;
attribute vec3 a_normal;
#if defined(DETAIL_MAP) || defined(BASE_MAP)
attribute vec2 a_uv;
#endif
#ifdef DETAIL_MAP
varying vec2 v_uv;
#endif
#ifdef BASE_COLOR
attribute vec4 a_color;
varying vec4 v_color;
#endif
#ifdef BASE_MAP
uniform mat3 u_base_transform;
varying vec2 v_base_uv;
#endif
#ifdef DETAIL_NORMAL
attribute vec4 a_tangent;
varying vec4 v_tangent;
#endif

uniform mat4 u_modelview;
uniform mat4 u_projection;
uniform mat3 u_normal_matrix;

#ifdef MODE_SEM_VERTEX
varying vec2 v_matcap_uv;
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
	v_matcap_uv = matcap_sem(safe_normalize(n), safe_normalize(eye));
#else
	v_normal = n;
	v_eye = eye;
#endif
#ifdef DETAIL_MAP
	v_uv = a_uv;
#endif
#ifdef BASE_COLOR
	v_color = a_color;
#endif
#ifdef BASE_MAP
	v_base_uv = (u_base_transform * vec3(a_uv, 1.0)).xy;
#endif
#ifdef DETAIL_NORMAL
	// The model-view is a rotation: tangents turn as normals do.
	v_tangent = vec4(u_normal_matrix * a_tangent.xyz, a_tangent.w);
#endif
	gl_Position = u_projection * p;
}
