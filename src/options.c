#include "options.h"
#include "log.h"

#include <errno.h>
#include <getopt.h>
#include <stdlib.h>
#include <string.h>

static const char *const backend_names[] = {"auto", "kms", "osmesa", "egl-headless"};

const char *backend_name(enum backend_kind kind)
{
	return backend_names[kind];
}

void options_usage(FILE *out)
{
	fputs("Usage: matcap-kiosk [OPTION]...\n"
	      "Show a glTF model shaded with a matcap, fullscreen on DRM/KMS or offscreen.\n"
	      "\n"
	      "  -b, --backend=NAME   auto (default), kms, osmesa or egl-headless; auto picks\n"
	      "                       kms when a display is connected, else osmesa with --output\n"
	      "  -m, --model=FILE     a .gltf or .glb model (default: a built-in torus knot)\n"
	      "  -c, --matcap=PATH    a PNG/JPEG matcap, or a folder of them (name order)\n"
	      "  -o, --output=FILE    write the last frame as PNG (offscreen backends)\n"
	      "  -s, --size=WxH       offscreen frame size (default 1280x720)\n"
	      "      --mode=MODE      normal, view (default), sem-vertex or sem-fragment\n"
	      "      --ortho          orthographic camera\n"
	      "      --yaw=DEG        turn the model about the vertical axis\n"
	      "      --pitch=DEG      tilt the model about the horizontal axis\n"
	      "      --rotate=DEG     panel rotation: 0, 90, 180 or 270\n"
	      "      --frames=N       frames to draw offscreen (default 1)\n"
	      "      --stats          print frame timings and peak memory\n"
	      "      --shader-dir=DIR read shaders from DIR instead of the built-in copy\n"
	      "  -q, --quiet          errors and warnings only\n"
	      "  -v, --verbose        debug messages too\n"
	      "  -h, --help           this text\n"
	      "  -V, --version        the version\n",
	      out);
}

static int parse_int(const char *opt, const char *s, int lo, int hi, int *out)
{
	char *end;
	long v;

	errno = 0;
	v = strtol(s, &end, 10);
	if (errno || end == s || *end || v < lo || v > hi) {
		log_err("--%s: '%s' is not a whole number from %d to %d", opt, s, lo, hi);
		return -EINVAL;
	}
	*out = (int)v;
	return 0;
}

static int parse_double(const char *opt, const char *s, double *out)
{
	char *end;

	errno = 0;
	*out = strtod(s, &end);
	if (errno || end == s || *end || *out != *out) {
		log_err("--%s: '%s' is not a number", opt, s);
		return -EINVAL;
	}
	return 0;
}

static int parse_size(const char *s, int *w, int *h)
{
	char *end;
	long a, b;

	errno = 0;
	a = strtol(s, &end, 10);
	if (!errno && *end == 'x') {
		char *end2;

		b = strtol(end + 1, &end2, 10);
		if (!errno && !*end2 && end2 != end + 1 && a >= 16 && b >= 16 && a <= 8192 &&
		    b <= 8192) {
			*w = (int)a;
			*h = (int)b;
			return 0;
		}
	}
	log_err("--size: '%s' is not WIDTHxHEIGHT with each side from 16 to 8192", s);
	return -EINVAL;
}

static int parse_choice(const char *opt, const char *s, const char *const *names, int n, int *out)
{
	for (int i = 0; i < n; i++)
		if (strcmp(s, names[i]) == 0) {
			*out = i;
			return 0;
		}
	log_err("--%s: '%s' is not one of the accepted values", opt, s);
	return -EINVAL;
}

enum {
	OPT_MODE = 256,
	OPT_ORTHO,
	OPT_YAW,
	OPT_PITCH,
	OPT_ROTATE,
	OPT_FRAMES,
	OPT_STATS,
	OPT_SHADERS
};

static const struct option long_options[] = {{"backend", required_argument, NULL, 'b'},
					     {"model", required_argument, NULL, 'm'},
					     {"matcap", required_argument, NULL, 'c'},
					     {"output", required_argument, NULL, 'o'},
					     {"size", required_argument, NULL, 's'},
					     {"mode", required_argument, NULL, OPT_MODE},
					     {"ortho", no_argument, NULL, OPT_ORTHO},
					     {"yaw", required_argument, NULL, OPT_YAW},
					     {"pitch", required_argument, NULL, OPT_PITCH},
					     {"rotate", required_argument, NULL, OPT_ROTATE},
					     {"frames", required_argument, NULL, OPT_FRAMES},
					     {"stats", no_argument, NULL, OPT_STATS},
					     {"shader-dir", required_argument, NULL, OPT_SHADERS},
					     {"quiet", no_argument, NULL, 'q'},
					     {"verbose", no_argument, NULL, 'v'},
					     {"help", no_argument, NULL, 'h'},
					     {"version", no_argument, NULL, 'V'},
					     {NULL, 0, NULL, 0}};

static int apply(struct options *o, int c, const char *arg)
{
	int v;

	switch (c) {
	case 'b':
		if (parse_choice("backend", arg, backend_names, 4, &v))
			return -EINVAL;
		o->backend = (enum backend_kind)v;
		return 0;
	case 'm':
		o->model = arg;
		return 0;
	case 'c':
		o->matcap = arg;
		return 0;
	case 'o':
		o->output = arg;
		return 0;
	case 's':
		return parse_size(arg, &o->width, &o->height);
	case OPT_MODE:
		if (shading_mode_parse(arg, &o->mode) == 0)
			return 0;
		log_err("--mode: '%s' is not normal, view, sem-vertex or sem-fragment", arg);
		return -EINVAL;
	case OPT_ORTHO:
		o->ortho = true;
		return 0;
	case OPT_YAW:
		return parse_double("yaw", arg, &o->yaw);
	case OPT_PITCH:
		return parse_double("pitch", arg, &o->pitch);
	case OPT_ROTATE:
		if (parse_int("rotate", arg, 0, 270, &o->rotation) || o->rotation % 90) {
			log_err("--rotate: '%s' is not 0, 90, 180 or 270", arg);
			return -EINVAL;
		}
		return 0;
	case OPT_FRAMES:
		return parse_int("frames", arg, 1, 100000000, &o->frames);
	case OPT_STATS:
		o->stats = true;
		return 0;
	case OPT_SHADERS:
		o->shader_dir = arg;
		return 0;
	case 'q':
		o->verbosity = -1;
		return 0;
	case 'v':
		o->verbosity = 1;
		return 0;
	case 'h':
		o->help = true;
		return 0;
	case 'V':
		o->version = true;
		return 0;
	default:
		return -EINVAL; /* getopt has said what was wrong */
	}
}

int options_parse(struct options *o, int argc, char **argv)
{
	int c;

	memset(o, 0, sizeof(*o));
	o->width = 1280;
	o->height = 720;
	o->mode = SHADING_VIEW;
	o->frames = 1;
	o->pitch = 20.0;
	o->yaw = -30.0;
	optind = 1;
	opterr = 1;
	while ((c = getopt_long(argc, argv, "b:m:c:o:s:qvhV", long_options, NULL)) != -1)
		if (apply(o, c, optarg))
			return -EINVAL;
	if (optind < argc) {
		log_err("unexpected argument '%s' (see --help)", argv[optind]);
		return -EINVAL;
	}
	return 0;
}
