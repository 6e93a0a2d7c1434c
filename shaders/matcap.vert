// One vertex shader for every mode; the program is compiled with exactly
// one of MODE_NORMAL, MODE_VIEW, MODE_SEM_VERTEX, MODE_SEM_FRAGMENT, and
// CAMERA_ORTHO when the projection is orthographic. DETAIL_MAP and
// DETAIL_NORMAL add the UV and the tangent frame, and only then; BASE_COLOR
// the vertex colour, BASE_MAP the UV through the base map's transform,
// EMISSIVE_MAP the UV through the emissive map's own, EMISSIVE_UV1 its UV
// the second set (a_uv1: a map on another TEXCOORD_n than the base map).
// SKIN_BONES (a model that plays its animation on the GPU) poses each
// vertex by its four bones of the palette: rows of 3x4 matrices that hold
// the node worlds, inverse binds and the model's fit. MORPH_TARGETS (with
// SKIN_BONES only) adds the morph targets first (morph.glsl, before this).

attribute vec3 a_position;
attribute vec3 a_normal;
#if defined(DETAIL_MAP) || defined(BASE_MAP) || defined(EMISSIVE_MAP)
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
#ifdef EMISSIVE_MAP
uniform mat3 u_emissive_transform;
varying vec2 v_emissive_uv;
#endif
#ifdef EMISSIVE_UV1
attribute vec2 a_uv1;
#endif
#ifdef DETAIL_NORMAL
attribute vec4 a_tangent;
varying vec4 v_tangent;
#endif

#ifdef SKIN_BONES
attribute vec4 a_joints;
attribute vec4 a_weights;
uniform vec4 u_bones[SKIN_BONES * 3];
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
#ifdef SKIN_BONES
	// The weights' blend of the bones' rows, over their sum (as the CPU
	// path: scene/anim/anim_play.c); every vertex has a bone of weight.
	vec3 own = a_position, own_normal = a_normal;
#ifdef MORPH_TARGETS
	morph(own, own_normal);
#endif
	vec4 r0 = vec4(0.0), r1 = vec4(0.0), r2 = vec4(0.0);
	float total = a_weights.x + a_weights.y + a_weights.z + a_weights.w;
	for (int k = 0; k < 4; k++) {
		float w = a_weights[k] / total;
		int j = int(a_joints[k] + 0.5) * 3;
		r0 += w * u_bones[j];
		r1 += w * u_bones[j + 1];
		r2 += w * u_bones[j + 2];
	}
	vec4 at = vec4(own, 1.0);
	vec3 posed = vec3(dot(r0, at), dot(r1, at), dot(r2, at));
	vec3 turned = vec3(dot(r0.xyz, own_normal), dot(r1.xyz, own_normal), dot(r2.xyz, own_normal));
	vec4 p = u_modelview * vec4(posed, 1.0);
	vec3 n = u_normal_matrix * safe_normalize(turned);
#else
	vec4 p = u_modelview * vec4(a_position, 1.0);
	vec3 n = u_normal_matrix * a_normal;
#endif
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
#ifdef EMISSIVE_MAP
#ifdef EMISSIVE_UV1
	v_emissive_uv = (u_emissive_transform * vec3(a_uv1, 1.0)).xy;
#else
	v_emissive_uv = (u_emissive_transform * vec3(a_uv, 1.0)).xy;
#endif
#endif
#ifdef DETAIL_NORMAL
	// The model-view is a rotation: tangents turn as normals do.
	v_tangent = vec4(u_normal_matrix * a_tangent.xyz, a_tangent.w);
#endif
	gl_Position = u_projection * p;
}
