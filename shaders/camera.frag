// The camera frame to RGB, compiled with exactly one of CAMERA_RGB,
// CAMERA_SEMI (NV12, NV21), CAMERA_PLANAR (YUV420, YVU420) or
// CAMERA_PACKED (YUYV, UYVY). The textures hold the frame's bytes as
// uploaded (LUMINANCE, LUMINANCE_ALPHA, RGB, RGBA) or as imported from
// the dmabuf (R8, GR88, RGBA): u_sel0..3 pick a byte out of a texel
// either way. The YCbCr matrix and range come from camera_math.c.

varying vec2 v_uv;

uniform sampler2D u_tex0;
uniform sampler2D u_tex1;
uniform sampler2D u_tex2;
// v_uv is kept inside the picture by half a texel (u_clamp: min xy, max
// xy), then scaled to the part of each texture that holds the picture
// (a texture as wide as the stride is wider than the picture).
uniform vec4 u_clamp;
uniform vec2 u_scale0;
uniform vec2 u_scale1;
uniform vec4 u_sel0;
uniform vec4 u_sel1;
uniform vec4 u_sel2;
uniform vec4 u_sel3;
uniform mat3 u_yuv;
uniform vec3 u_offset;
// CAMERA_PACKED: the picture's width in pixels, the texture's in texels.
uniform vec2 u_packed;

void main()
{
	vec2 uv = clamp(v_uv, u_clamp.xy, u_clamp.zw);
#if defined(CAMERA_RGB)
	vec4 t = texture2D(u_tex0, uv * u_scale0);
	gl_FragColor = vec4(dot(t, u_sel0), dot(t, u_sel1), dot(t, u_sel2), 1.0);
#else
#ifdef CAMERA_PACKED
	// Two pixels per texel: sampled exactly (nearest), the pixel's own
	// luma picked by the parity of its column.
	float x = floor(uv.x * u_packed.x);
	float pair = floor(x * 0.5);
	vec4 t = texture2D(u_tex0, vec2((pair + 0.5) / u_packed.y, uv.y * u_scale0.y));
	float y = x - 2.0 * pair < 0.5 ? dot(t, u_sel0) : dot(t, u_sel2);
	vec2 c = vec2(dot(t, u_sel1), dot(t, u_sel3));
#else
	float y = texture2D(u_tex0, uv * u_scale0).r;
#ifdef CAMERA_SEMI
	vec4 t = texture2D(u_tex1, uv * u_scale1);
	vec2 c = vec2(dot(t, u_sel0), dot(t, u_sel1));
#else
	vec2 c = vec2(texture2D(u_tex1, uv * u_scale1).r, texture2D(u_tex2, uv * u_scale1).r);
#endif
#endif
	gl_FragColor = vec4(clamp(u_yuv * vec3(y, c) + u_offset, 0.0, 1.0), 1.0);
#endif
}
