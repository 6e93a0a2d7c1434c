// The matcap lookup, and the optional layers over it. The default float
// precision (mediump unless the build asks otherwise) is set in the header
// that src/render/shader.c puts before this.

#ifdef MODE_SEM_VERTEX
varying vec2 v_matcap_uv;
#else
varying SHADE_P vec3 v_normal;
varying SHADE_P vec3 v_eye;
#endif

uniform sampler2D u_matcap;
// Where the matcap is mipmapped (src/render/render.c does for a model no
// wider on screen than the matcap), a model small on screen reads its disk
// averaged, not aliased. GL picks the level from the
// larger of a pixel's two derivatives, which across a thin part (a knot's
// tube) blurs the disk along the tube as well; the SEM modes map the
// reflection, which sweeps the disk twice as fast, fastest at the rim,
// where that blur would bleed the rim inwards. One level finer measured
// best in every mode (tests/bench/report: at two finer, SEM aliases again).
#define MATCAP_LOD_BIAS -1.0

#ifdef DETAIL_MAP
// highp where the GPU has it: at mediump (10-bit mantissa) a UV in
// [0.5, 1) moves in steps of 1/2048, half a texel of a 1024 map, and a
// repeated map's UVs beyond 1 fare worse.
#ifdef GL_FRAGMENT_PRECISION_HIGH
varying highp vec2 v_uv;
#else
varying vec2 v_uv;
#endif
uniform sampler2D u_detail;
#endif
#ifdef DETAIL_NORMAL
varying SHADE_P vec4 v_tangent;
#endif
#ifdef BASE_COLOR
varying vec4 v_color;
#endif
#ifdef BASE_MAP
#ifdef GL_FRAGMENT_PRECISION_HIGH
varying highp vec2 v_base_uv;
#else
varying vec2 v_base_uv;
#endif
uniform sampler2D u_base_map;
// 1 where this draw's material has a base map, 0 where it has none: a
// program is shared by ranges with and without one (set per draw).
uniform float u_reads_base_map;
#endif
#ifdef EMISSIVE
uniform SHADE_P vec3 u_emissive; // emissiveFactor x strength, linear
#endif
#ifdef EMISSIVE_MAP
#ifdef GL_FRAGMENT_PRECISION_HIGH
varying highp vec2 v_emissive_uv;
#else
varying vec2 v_emissive_uv;
#endif
uniform sampler2D u_emissive_map; // sRGB as stored
#endif
#if defined(ALPHA_MASK) || defined(ALPHA_BLEND)
uniform vec2 u_alpha; // the material's alpha factor, and its alphaCutoff
#endif
#ifdef IRIDESCENCE
uniform SHADE_P vec4 u_iridescence; // hue range, hue average, hue shift, opacity
#ifdef IRIDESCENCE_RAMP
uniform sampler2D u_ramp;
#else
uniform vec2 u_hsv; // saturation, value
#endif
#endif
#ifdef LIT
uniform SHADE_P vec3 u_light; // unit, in view space: fixed to the camera
uniform SHADE_P vec3 u_base_color;
uniform SHADE_P float u_shininess;
#endif

void main()
{
#ifdef BASE_MAP
	vec4 base_map = texture2D(u_base_map, v_base_uv);
	float reads_map = u_reads_base_map;
#else
	vec4 base_map = vec4(1.0);
	float reads_map = 0.0;
#endif
#ifdef UNLIT
	// KHR_materials_unlit: the base colour as it is, no matcap, no light.
#ifdef BASE_COLOR
	vec3 color = linear_to_srgb(base_linear(v_color.rgb, base_map.rgb, reads_map));
#else
	vec3 color = vec3(1.0);
#endif
#else
#ifdef DETAIL_MAP
	vec4 detail = texture2D(u_detail, v_uv);
#endif
#if defined(MODE_SEM_VERTEX)
	vec3 color = texture2D(u_matcap, v_matcap_uv, MATCAP_LOD_BIAS).rgb;
#else
	SHADE_P vec3 n = safe_normalize(v_normal);
	SHADE_P vec3 e = safe_normalize(v_eye);
#ifdef DOUBLE_SIDED
	// A back face shows its other side: its normal turned, as glTF says.
	if (!gl_FrontFacing)
		n = -n;
#endif
#ifdef DETAIL_NORMAL
	n = detail_normal(n, v_tangent, detail.rg);
#endif
#if defined(LIT)
	vec3 color = lit_blinn_phong(n, e, u_light, u_base_color, u_shininess);
#else
#if defined(MODE_NORMAL)
	vec2 uv = matcap_normal(n);
#elif defined(MODE_VIEW)
	vec2 uv = matcap_view(n, e);
#else
	vec2 uv = matcap_sem(n, e);
#endif
	vec3 color = texture2D(u_matcap, uv, MATCAP_LOD_BIAS).rgb;
#endif
#ifdef IRIDESCENCE
#ifdef DETAIL_MAP
	float map_a = detail.a;
#else
	float map_a = 1.0;
#endif
	SHADE_P float hue = iridescence_hue(dot(n, e), u_iridescence.x, u_iridescence.y, u_iridescence.z,
				    map_a);
#ifdef IRIDESCENCE_RAMP
	vec3 film = texture2D(u_ramp, vec2(fract(hue), 0.5)).rgb;
#else
	vec3 film = hsv_to_rgb(hue, u_hsv.x, u_hsv.y);
#endif
	color = mix(color, film, u_iridescence.w);
#endif
#endif
#ifdef BASE_COLOR
	color = base_color(color, v_color.rgb, base_map.rgb, reads_map);
#endif
#ifdef DETAIL_MAP
	color *= detail.b; // ambient occlusion
#endif
#endif // UNLIT
#ifdef EMISSIVE
#ifdef EMISSIVE_MAP
	vec3 glow = u_emissive * srgb_to_linear(texture2D(u_emissive_map, v_emissive_uv).rgb);
#else
	vec3 glow = u_emissive;
#endif
	color = add_emission(color, glow);
#endif
#if defined(ALPHA_MASK) || defined(ALPHA_BLEND)
	// glTF's alpha: baseColorFactor's times the map's, where the draw
	// reads its material's map, times COLOR_0's (v_color.a,
	// src/scene/mesh/mesh.h).
	float alpha = u_alpha.x * mix(1.0, base_map.a, reads_map) * v_color.a;
#endif
#ifdef ALPHA_MASK
	if (alpha < u_alpha.y)
		discard;
#endif
#ifdef ALPHA_BLEND
	gl_FragColor = vec4(color, alpha);
#else
	gl_FragColor = vec4(color, 1.0);
#endif
}
