/* bake OUTDIR [SIZE]: write OUTDIR/<name>.png for every baked material.
 * `make matcaps` runs `build/bake matcaps 256` to rebuild the shipped PNGs
 * byte for byte (see matcaps/README.md). */
#include "render/bake.h"
#include "util/image.h"
#include "util/log.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define DEFAULT_SIZE 256

static void usage(FILE *f)
{
	fprintf(f,
		"usage: bake OUTDIR [SIZE]\n"
		"Write OUTDIR/<material>.png for every built-in material, SIZE x SIZE\n"
		"pixels (default %d, at most %d). OUTDIR must exist.\n"
		"Materials:",
		DEFAULT_SIZE, IMAGE_MAX_SIDE);
	for (int m = 0; m < BAKE_COUNT; m++)
		fprintf(f, " %s", bake_name((enum bake_material)m));
	fprintf(f, "\n");
}

static int parse_size(const char *arg, int *size)
{
	char *end;
	long v;

	errno = 0;
	v = strtol(arg, &end, 10);
	if (errno || end == arg || *end || v < 1 || v > IMAGE_MAX_SIDE) {
		log_err("bake: SIZE '%s' is not a whole number in 1..%d", arg, IMAGE_MAX_SIDE);
		return -EINVAL;
	}
	*size = (int)v;
	return 0;
}

static int bake_one(enum bake_material m, const char *outdir, int size)
{
	struct image img = {0, 0, NULL};
	char path[4096];
	int n, ret;

	n = snprintf(path, sizeof(path), "%s/%s.png", outdir, bake_name(m));
	if (n < 0 || (size_t)n >= sizeof(path)) {
		log_err("bake: output path under '%s' is too long", outdir);
		return -ENAMETOOLONG;
	}
	ret = bake_matcap(m, size, &img);
	if (ret)
		goto out;
	ret = image_write_png(path, &img);
	if (ret)
		goto out;
	log_info("bake: wrote %s (%dx%d)", path, size, size);
out:
	image_release(&img);
	return ret;
}

int main(int argc, char **argv)
{
	int size = DEFAULT_SIZE;

	if (argc >= 2 && (!strcmp(argv[1], "--help") || !strcmp(argv[1], "-h"))) {
		usage(stdout);
		return 0;
	}
	if (argc < 2 || argc > 3 || argv[1][0] == '\0') {
		usage(stderr);
		return 2;
	}
	if (argc == 3 && parse_size(argv[2], &size))
		return 2;
	for (int m = 0; m < BAKE_COUNT; m++)
		if (bake_one((enum bake_material)m, argv[1], size))
			return 1;
	return 0;
}
