// Matcap mappings: a unit view-space normal (and, for the view-dependent
// modes, the direction from the eye) to a texture coordinate. t = 0 is the
// image's top row, so "up" in view space is flipped.
// Mirrored line for line in tests/oracle/shading_mirror.h, the reference of the tests.

// Precision. Mali and Adreno GPUs run mediump in 16 bits (binary16: 11
// significant bits). tests/unit/test_fp16.c rounds the C mirror so and
// finds mediump enough for the matcap mappings (under 3/4 of a texel of
// a 256 matcap) but not for the lit mode's highlight (pow amplifies the
// error of n.h: 6/255 at shininess 32) nor for the iridescent hue (1.4 to
// 8/255): there the normal and eye vectors, the hue and the lit terms are
// SHADE_P, highp where the GPU has it (within 1/255 then); elsewhere the
// stage's default. PRECISION_HIGHP makes every float highp (src/render/render.c
// sets it on a CPU rasteriser, where 16-bit floats are emulated, slower).
#if defined(PRECISION_HIGHP) && defined(GL_FRAGMENT_PRECISION_HIGH)
precision highp float;
#endif
#if defined(GL_FRAGMENT_PRECISION_HIGH) && (defined(LIT) || defined(IRIDESCENCE))
#define SHADE_P highp
#else
#define SHADE_P
#endif

SHADE_P vec3 safe_normalize(SHADE_P vec3 v)
{
	// An interpolated normal can shrink to nothing between opposed
	// vertices; fall back to facing the viewer instead of NaN.
	SHADE_P float l2 = dot(v, v);
	return l2 > 1.0e-6 ? v * inversesqrt(l2) : vec3(0.0, 0.0, 1.0);
}

// Normal mode: the normal's xy is the position on the disk.
vec2 matcap_normal(vec3 n)
{
	return vec2(n.x, -n.y) * 0.5 + 0.5;
}

// As three.js and Blender do: a basis around the view direction, so a flat
// surface off the screen centre does not stretch. The 0.495 keeps the rim
// inside the disk.
vec2 matcap_view(vec3 n, vec3 eye_to_point)
{
	vec3 v = -eye_to_point;
	float h2 = v.z * v.z + v.x * v.x;
	vec3 x = h2 > 1.0e-4 ? vec3(v.z, 0.0, -v.x) * inversesqrt(h2) : vec3(1.0, 0.0, 0.0);
	vec3 y = cross(v, x);
	return vec2(dot(x, n), -dot(y, n)) * 0.495 + 0.5;
}

// SEM: spherical environment mapping of the reflected eye vector,
// uv = r.xy / m + 0.5 with m = 2 |r + (0,0,1)|. Since r.xy = (r + z).xy,
// r.xy / m is half the xy of h = normalize(r + z): the same value, written
// so that the singularity at r = (0,0,-1), where m = 0, has a safe limit.
// Near it (r + z).z = 1 + r.z shrinks as |r.xy|^2, faster than r.xy, so h
// reaches the rim (h.z = 0), as r.xy / m does, at an angle that
// depends on the side it comes from: every rim point stands for r = -z.
// The fallback takes the rim point in n's direction, which is r.xy's
// there. (h = n, the textbook's limit, holds only at the screen's centre:
// elsewhere the singular n leans towards the eye by half the view angle,
// and n would land about 4 texels of a 256 matcap inside the rim at a
// 16:9 frame's corners.) tests/unit/test_stability.c checks the rim in
// double, float and binary16.
vec2 matcap_sem(vec3 n, vec3 eye_to_point)
{
	vec3 h = reflect(eye_to_point, n) + vec3(0.0, 0.0, 1.0);
	float l2 = dot(h, h);
	h = l2 > 1.0e-6 ? h * inversesqrt(l2) : safe_normalize(vec3(n.xy, 0.0));
	return vec2(h.x, -h.y) * 0.5 + 0.5;
}
