// A hotspot: a disc of its colour in a dark ring (it reads on a light
// matcap and a dark one), a badge's number dark on it, faded at the
// silhouette. Premultiplied: blended ONE, ONE_MINUS_SRC_ALPHA.

varying vec2 v_at;

uniform vec4 u_color;  // straight RGBA
uniform float u_fade;  // 0..1
uniform float u_digit; // the glyph in u_digits; -1: a plain dot
uniform float u_pixels; // the radius in pixels: the edge's antialiasing
uniform sampler2D u_digits; // 10 glyphs of 3x5, 4 texels apart

void main()
{
	float r = length(v_at);
	float edge = clamp((1.0 - r) * u_pixels, 0.0, 1.0);
	vec3 c = r > 0.72 ? vec3(0.08) : u_color.rgb;
	float a = u_color.a * u_fade * edge;

	if (u_digit >= 0.0) {
		vec2 g = vec2((v_at.x + 0.33) / 0.66, (0.5 - v_at.y) / 1.0);

		if (g.x >= 0.0 && g.x < 1.0 && g.y >= 0.0 && g.y < 1.0) {
			vec2 uv = vec2((u_digit * 4.0 + g.x * 3.0) / 40.0, g.y);

			c = mix(c, vec3(0.08), texture2D(u_digits, uv).a);
		}
	}
	gl_FragColor = vec4(c * a, a);
}
