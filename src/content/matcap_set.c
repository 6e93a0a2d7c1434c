#include "content/matcap_set.h"
#include "util/file.h"
#include "util/log.h"

#include <stdbool.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

struct matcap_set {
	int count;
	char **paths;
};

static const char *const image_exts[] = {"png", "jpg", "jpeg", "webp", NULL};

static int add_path(struct matcap_set *s, const char *dir, const char *name)
{
	size_t n = strlen(dir) + strlen(name) + 2;
	char **grown = realloc(s->paths, sizeof(*grown) * (size_t)(s->count + 1));

	if (!grown)
		return -ENOMEM;
	s->paths = grown;
	s->paths[s->count] = malloc(n);
	if (!s->paths[s->count])
		return -ENOMEM;
	if (dir[0])
		snprintf(s->paths[s->count], n, "%s/%s", dir, name);
	else
		snprintf(s->paths[s->count], n, "%s", name);
	s->count++;
	return 0;
}

static int scan_folder(struct matcap_set *s, const char *path)
{
	int ret = file_list_folder(path, image_exts, &s->paths, &s->count);

	if (ret) {
		log_err("%s: cannot open folder: %s", path, strerror(-ret));
	} else if (s->count == 0) {
		log_err("%s: no .png, .jpg, .jpeg or .webp files in the folder", path);
		ret = -ENOENT;
	}
	return ret;
}

struct matcap_set *matcap_set_open(const char *path)
{
	struct matcap_set *s = calloc(1, sizeof(*s));
	struct stat st;
	int ret;

	if (!s)
		return NULL;
	if (stat(path, &st)) {
		log_err("%s: %s", path, strerror(errno));
		ret = -errno;
	} else if (S_ISDIR(st.st_mode)) {
		ret = scan_folder(s, path);
	} else {
		ret = add_path(s, "", path);
	}
	if (ret) {
		matcap_set_free(s);
		return NULL;
	}
	return s;
}

void matcap_set_free(struct matcap_set *s)
{
	if (!s)
		return;
	for (int i = 0; i < s->count; i++)
		free(s->paths[i]);
	free(s->paths);
	free(s);
}

int matcap_set_count(const struct matcap_set *s)
{
	return s->count;
}

const char *matcap_set_path(const struct matcap_set *s, int index)
{
	return s->paths[((index % s->count) + s->count) % s->count];
}

/* The file name of path without its folder and, where it has one, its
 * extension: what [scene] matcap_first names. */
static bool names(const char *path, const char *name)
{
	const char *base = strrchr(path, '/');
	const char *dot;
	size_t len;

	base = base ? base + 1 : path;
	if (!strcmp(base, name))
		return true;
	dot = strrchr(base, '.');
	len = dot ? (size_t)(dot - base) : strlen(base);
	return strlen(name) == len && !strncmp(base, name, len);
}

int matcap_set_start_at(struct matcap_set *s, const char *name)
{
	char **turned;
	int at = 0;

	while (at < s->count && !names(s->paths[at], name))
		at++;
	if (at == s->count)
		return -ENOENT;
	if (at == 0)
		return 0;
	turned = malloc(sizeof(*turned) * (size_t)s->count);
	if (!turned)
		return -ENOMEM;
	/* Turned, not moved: the name order goes on from the one named. */
	for (int i = 0; i < s->count; i++)
		turned[i] = s->paths[(at + i) % s->count];
	free(s->paths);
	s->paths = turned;
	return 0;
}

bool matcap_set_has(const struct matcap_set *s, const char *name)
{
	for (int i = 0; i < s->count; i++)
		if (names(s->paths[i], name))
			return true;
	return false;
}

void matcap_measure(const struct image *img, struct matcap_tint *out)
{
	double r = (img->width < img->height ? img->width : img->height) / 2.0;
	double chroma = 0, value = 0;
	long n = 0;

	for (int y = 0; y < img->height; y++)
		for (int x = 0; x < img->width; x++) {
			const uint8_t *p = img->rgba + ((size_t)y * (size_t)img->width + x) * 4;
			double dx = x + 0.5 - img->width / 2.0, dy = y + 0.5 - img->height / 2.0;
			int hi = p[0] > p[1] ? p[0] : p[1], lo = p[0] < p[1] ? p[0] : p[1];

			if (dx * dx + dy * dy > r * r)
				continue;
			hi = p[2] > hi ? p[2] : hi;
			lo = p[2] < lo ? p[2] : lo;
			chroma += hi - lo;
			value += hi;
			n++;
		}
	out->chroma = n ? chroma / (double)n : 0;
	out->value = n ? value / (double)n : 0;
}

/* Small enough to decode a folder quickly, large enough for a mean. */
#define MATCAP_MEASURE_SIDE 64
#define MATCAP_BRIGHT	    64.0

int matcap_set_most_neutral(const struct matcap_set *s)
{
	const struct image_fit fit = {MATCAP_MEASURE_SIDE, 0};
	int best = -1;
	struct matcap_tint best_t = {0, 0};

	for (int i = 0; i < s->count && i < MATCAP_MEASURED_MAX; i++) {
		struct image img;
		struct matcap_tint t;

		if (image_load_fit(s->paths[i], &fit, &img))
			continue;
		matcap_measure(&img, &t);
		image_release(&img);
		bool bright = t.value >= MATCAP_BRIGHT, best_bright = best_t.value >= MATCAP_BRIGHT;
		if (best < 0 || bright > best_bright ||
		    (bright == best_bright && t.chroma < best_t.chroma)) {
			best = i;
			best_t = t;
		}
	}
	return best;
}
