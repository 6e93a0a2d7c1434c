// The optional features' math, for the fragment shader only:
// each function is compiled in only when its feature's #define is set.
// Mirrored line for line in tests/oracle/shading_mirror.h, the reference of the
// tests. SHADE_P (mapping.glsl) marks the values that mediump cannot carry.

#ifdef IRIDESCENCE
// Iridescence: the hue of a thin film from the angle between normal and view.
// (n.e)^2 is a product, not pow(n.e, 2.0): pow of a negative base is
// undefined in GLSL ES, and n.e < 0 on every surface facing the eye (e
// points from the eye to the surface). map_a is the detail map's alpha,
// 1 where the hue is not shifted.
SHADE_P float iridescence_hue(SHADE_P float n_dot_e, SHADE_P float range, SHADE_P float average,
			      SHADE_P float shift, SHADE_P float map_a)
{
	return (1.0 - n_dot_e * n_dot_e) * range + average - shift * (1.0 - map_a);
}

// HSV to RGB: each channel a triangle wave of the hue, clamped to [0, 1].
// The hue is wrapped at its own precision: a hue of 2 turns at mediump is
// already 1/1024 of a turn off, 1.5/255 of colour.
vec3 hsv_to_rgb(SHADE_P float h, float s, float v)
{
	vec3 p = abs(fract(vec3(h) + vec3(1.0, 2.0 / 3.0, 1.0 / 3.0)) * 6.0 - 3.0);
	return v * mix(vec3(1.0), clamp(p - 1.0, 0.0, 1.0), s);
}
#endif

#ifdef DETAIL_NORMAL
// The packed detail map's tangent-space normal: xy in rg, z rebuilt (the
// map holds unit normals), turned into view space by the vertex's frame,
// made orthogonal again after interpolation bent it.
SHADE_P vec3 detail_normal(SHADE_P vec3 n, SHADE_P vec4 tangent, SHADE_P vec2 rg)
{
	SHADE_P vec2 xy = rg * 2.0 - 1.0;
	SHADE_P float z = sqrt(max(1.0 - dot(xy, xy), 0.0));
	SHADE_P vec3 t = safe_normalize(tangent.xyz - n * dot(n, tangent.xyz));
	SHADE_P vec3 b = cross(n, t) * (tangent.w < 0.0 ? -1.0 : 1.0);
	return safe_normalize(t * xy.x + b * xy.y + n * z);
}
#endif

#ifdef LIT
// Lit, to compare with the matcap: diffuse plus Blinn-Phong specular, the light
// fixed to the camera (l in view space). pow(n.h, 48) multiplies the
// error of n.h by 48: at mediump that is 6/255 of colour, hence SHADE_P.
const float LIT_AMBIENT = 0.15;
const float LIT_SPECULAR = 0.5;

SHADE_P vec3 lit_blinn_phong(SHADE_P vec3 n, SHADE_P vec3 e, SHADE_P vec3 l, SHADE_P vec3 base,
			     SHADE_P float shininess)
{
	SHADE_P float diffuse = max(dot(n, l), 0.0);
	SHADE_P vec3 h = safe_normalize(l - e);
	SHADE_P float specular = diffuse > 0.0 ? pow(max(dot(n, h), 0.0), shininess) : 0.0;
	return base * (LIT_AMBIENT + (1.0 - LIT_AMBIENT) * diffuse) + vec3(LIT_SPECULAR * specular);
}
#endif

#if defined(BASE_COLOR) || defined(EMISSIVE)
// sRGB's transfer functions, exact (piecewise), as three.js's
// sRGBTransferEOTF and sRGBTransferOETF.
vec3 srgb_to_linear(vec3 c)
{
	return mix(pow(c * 0.9478672986 + 0.0521327014, vec3(2.4)), c * 0.0773993808,
		   step(c, vec3(0.04045)));
}

vec3 linear_to_srgb(vec3 c)
{
	return mix(pow(c, vec3(0.41666)) * 1.055 - 0.055, c * 12.92, step(c, vec3(0.0031308)));
}

#endif

#ifdef BASE_COLOR
// The base colour, linear: rgb: baseColorFactor x COLOR_0, linear; map:
// the base map's texel, sRGB, applied where reads_map is 1 (the range's
// material has a map: u_reads_base_map). The map is filtered as stored,
// before decoding: GLES2 has no sRGB textures (three.js on WebGL 1
// without EXT_sRGB does the same).
vec3 base_linear(vec3 rgb, vec3 map, float reads_map)
{
	return rgb * mix(vec3(1.0), srgb_to_linear(map), reads_map);
}

// three.js's MeshMatcapMaterial: the matcap (sRGB) times the base colour,
// multiplied in linear light and encoded again. Not in the mirror:
// tests/oracle/base_color_check.c is its reference (and of unlit and
// emission below).
vec3 base_color(vec3 matcap, vec3 rgb, vec3 map, float reads_map)
{
	return linear_to_srgb(srgb_to_linear(matcap) * base_linear(rgb, map, reads_map));
}
#endif

#ifdef EMISSIVE
// glTF's emission: light added to the shaded colour (sRGB) in linear light,
// as three.js adds it, then encoded again (clamped to white, as the
// framebuffer does). light: emissiveFactor x strength x the map's texel,
// linear.
vec3 add_emission(vec3 color, vec3 light)
{
	return linear_to_srgb(min(srgb_to_linear(color) + light, vec3(1.0)));
}
#endif
