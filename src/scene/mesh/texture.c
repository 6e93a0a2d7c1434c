#include "scene/mesh/texture.h"

#include <errno.h>
#include <math.h>
#include <sys/sysinfo.h>

#define TEXTURE_MEMORY_MIN ((size_t)16 << 20)
#define TEXTURE_MEMORY_MAX ((size_t)256 << 20)

/* The texel index for coordinate x (in texels, centres at i + 0.5) on a
 * wrapping axis of n texels. */
static int wrap(long i, int n)
{
	long r = i % n;

	return (int)(r < 0 ? r + n : r);
}

void texture_sample(const struct image *img, double u, double v, double out[4])
{
	double x = u * img->width - 0.5, y = v * img->height - 0.5;
	double fx, fy;
	long x0, y0;

	if (!isfinite(x) || !isfinite(y) || fabs(x) > 1e9 || fabs(y) > 1e9)
		x = y = 0.0;
	x0 = (long)floor(x);
	y0 = (long)floor(y);
	fx = x - (double)x0;
	fy = y - (double)y0;
	for (int c = 0; c < 4; c++)
		out[c] = 0.0;
	for (int k = 0; k < 4; k++) {
		int tx = wrap(x0 + (k & 1), img->width), ty = wrap(y0 + (k >> 1), img->height);
		double w = ((k & 1) ? fx : 1.0 - fx) * ((k >> 1) ? fy : 1.0 - fy);
		const uint8_t *p = img->rgba + ((size_t)ty * (size_t)img->width + (size_t)tx) * 4;

		for (int c = 0; c < 4; c++)
			out[c] += w * p[c] / 255.0;
	}
}

double texture_height(const struct image *img, double u, double v)
{
	double t[4];

	texture_sample(img, u, v, t);
	return 0.30 * t[0] + 0.59 * t[1] + 0.11 * t[2];
}

int texture_resample(const struct image *src, int w, int h, struct image *out)
{
	int ret = image_alloc(out, w, h);

	if (ret)
		return ret;
	for (int y = 0; y < h; y++)
		for (int x = 0; x < w; x++) {
			double t[4];
			uint8_t *p = out->rgba + ((size_t)y * (size_t)w + (size_t)x) * 4;

			texture_sample(src, (x + 0.5) / w, (y + 0.5) / h, t);
			for (int c = 0; c < 4; c++)
				p[c] = (uint8_t)lround(t[c] * 255.0);
		}
	return 0;
}

int texture_pot(int n, int max)
{
	int p = 1;

	while (p < n && p < max)
		p *= 2;
	/* p is the power of two at or above n: step down when the one
	 * below is nearer, so a 600-texel map is not blown up to 1024. */
	if (p > 1 && p - n > n - p / 2)
		p /= 2;
	return p > max ? max : p;
}

size_t texture_memory_auto(uint64_t ram)
{
	uint64_t q = ram / 4;

	if (q < TEXTURE_MEMORY_MIN)
		return TEXTURE_MEMORY_MIN;
	return q > TEXTURE_MEMORY_MAX ? TEXTURE_MEMORY_MAX : (size_t)q;
}

size_t texture_memory_budget(double mib)
{
	struct sysinfo si;

	if (mib > 0)
		return (size_t)mib << 20;
	/* Unknown RAM: the smallest board the kiosk runs on (512 MB). */
	if (sysinfo(&si))
		return texture_memory_auto((uint64_t)512 << 20);
	return texture_memory_auto((uint64_t)si.totalram * si.mem_unit);
}
