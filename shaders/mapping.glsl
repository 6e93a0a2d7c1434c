// Matcap mappings: a unit view-space normal (and, for the view-dependent
// modes, the direction from the eye) to a texture coordinate. t = 0 is the
// image's top row, so "up" in view space is flipped.
// Mirrored line for line in src/shading.c, the reference of the tests.

vec3 safe_normalize(vec3 v)
{
	// An interpolated normal can shrink to nothing between opposed
	// vertices; fall back to facing the viewer instead of NaN.
	float l2 = dot(v, v);
	return l2 > 1.0e-6 ? v * inversesqrt(l2) : vec3(0.0, 0.0, 1.0);
}

// Seed 000: the normal's xy is the position on the disk.
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

// Seed 003: spherical environment mapping of the reflected eye vector,
// uv = r.xy / m + 0.5 with m = 2 |r + (0,0,1)|. Since r.xy = (r + z).xy,
// r.xy / m is half the xy of h = normalize(r + z): the same value, written
// so that the singularity at r = (0,0,-1), where m = 0, has a safe limit.
// There r + z = -2 (n.e) n + (e + z) shrinks along n, so h tends to n: on
// the rim, as the seed formula does from every side.
vec2 matcap_sem(vec3 n, vec3 eye_to_point)
{
	vec3 h = reflect(eye_to_point, n) + vec3(0.0, 0.0, 1.0);
	float l2 = dot(h, h);
	h = l2 > 1.0e-6 ? h * inversesqrt(l2) : n;
	return vec2(h.x, -h.y) * 0.5 + 0.5;
}
