/* matcap-kiosk: a glTF model shaded with a matcap, fullscreen on DRM/KMS
 * or offscreen. main() wires the pieces; each lives in its own file. */
#include "bake.h"
#include "display.h"
#include "gltf.h"
#include "image.h"
#include "kiosk.h"
#include "log.h"
#include "matcap_set.h"
#include "mesh.h"
#include "options.h"
#include "render.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <time.h>
#include <unistd.h>

#ifndef MK_VERSION
#define MK_VERSION "0.0.0"
#endif
#ifndef MK_MATCAP_DIR
#define MK_MATCAP_DIR "/usr/local/share/matcap-kiosk/matcaps"
#endif

#define KNOT_TUBULAR 256
#define KNOT_RADIAL  32

struct scene {
	struct mesh mesh;
	struct image matcap;	/* the first one shown */
	struct matcap_set *set; /* NULL: the built-in clay only */
};

static double now_ms(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_MONOTONIC, &ts);
	return ts.tv_sec * 1e3 + ts.tv_nsec / 1e6;
}

/* strict: a file the user named must load (a one-shot render is useless
 * with a substitute); otherwise the kiosk shows the built-in and says so. */
static int load_model(const struct options *o, bool strict, struct mesh *mesh)
{
	if (o->model) {
		int ret = gltf_load(o->model, mesh);

		if (!ret || strict)
			return ret;
		log_warn("showing the built-in torus knot instead of %s", o->model);
	}
	return mesh_torus_knot(mesh, KNOT_TUBULAR, KNOT_RADIAL);
}

static const char *default_matcaps(void)
{
	/* Installed data first; the source tree's folder when run from it. */
	if (access(MK_MATCAP_DIR, R_OK) == 0)
		return MK_MATCAP_DIR;
	return access("matcaps", R_OK) == 0 ? "matcaps" : NULL;
}

static int load_matcap(const struct options *o, bool strict, struct scene *s)
{
	const char *path = o->matcap ? o->matcap : default_matcaps();
	int ret = -ENOENT;

	s->set = path ? matcap_set_open(path) : NULL;
	if (s->set)
		ret = image_load(matcap_set_path(s->set, 0), &s->matcap);
	if (ret && strict && o->matcap)
		return ret;
	if (ret) {
		log_warn("using the built-in clay matcap");
		matcap_set_free(s->set);
		s->set = NULL;
		ret = bake_matcap(BAKE_CLAY_RED, 256, &s->matcap);
	}
	return ret;
}

static struct display *open_display(const struct options *o)
{
	struct display_config cfg = {.width = o->size[0], .height = o->size[1]};

	switch (o->backend) {
	case BACKEND_EGL_HEADLESS:
		return display_egl_new(&cfg);
	case BACKEND_KMS:
		log_err("kms: this build has no KMS backend yet");
		return NULL;
	default:
		return display_osmesa_new(&cfg);
	}
}

static int compare_double(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;

	return (x > y) - (x < y);
}

static void print_stats(double *times, int n, double first_frame_ms)
{
	struct rusage ru;

	qsort(times, (size_t)n, sizeof(*times), compare_double);
	getrusage(RUSAGE_SELF, &ru);
	printf("frames %d median_ms %.3f p90_ms %.3f first_frame_ms %.1f peak_rss_kib %ld\n", n,
	       times[n / 2], times[(n * 9) / 10], first_frame_ms, ru.ru_maxrss);
}

static struct view initial_view(const struct options *o)
{
	struct view v = {
	    .ortho = o->ortho, .rotation = o->rotation, .background = {0.06f, 0.06f, 0.07f}};

	v.orientation = quat_multiply(quat_from_axis_angle(1, 0, 0, o->pitch * M_PI / 180),
				      quat_from_axis_angle(0, 1, 0, o->yaw * M_PI / 180));
	return v;
}

static int render_frames(const struct options *o, struct display *d, struct renderer *r,
			 double start_ms)
{
	struct view v = initial_view(o);
	double *times = calloc((size_t)o->frames, sizeof(double));
	double first = 0;
	int ret = 0;

	if (!times)
		return -ENOMEM;
	for (int i = 0; i < o->frames && !ret; i++) {
		double t = now_ms();

		ret = d->begin_frame(d);
		if (!ret) {
			renderer_draw(r, &v, d->width, d->height);
			ret = d->present(d);
		}
		times[i] = now_ms() - t;
		if (i == 0)
			first = now_ms() - start_ms;
	}
	if (!ret && o->stats)
		print_stats(times, o->frames, first);
	free(times);
	return ret;
}

static int write_output(const struct options *o, struct display *d)
{
	struct image frame;
	int ret = d->read_frame(d, &frame);

	if (!ret)
		ret = image_write_png(o->output, &frame);
	if (!ret)
		log_info("wrote %s (%dx%d)", o->output, frame.width, frame.height);
	image_release(&frame);
	return ret;
}

static int run_live(const struct options *o, struct scene *s, struct display *d, struct renderer *r)
{
	/* The renderer already holds the first matcap and the mode. */
	struct kiosk k = {.display = d,
			  .renderer = r,
			  .matcaps = s->set,
			  .shown_matcap = 0,
			  .shown_mode = (enum shading_mode)o->mode,
			  .shown_ortho = o->ortho};
	struct app_config cfg = {
	    .turn_speed = M_PI / 2,
	    .turn_step = M_PI / 36,
	    .attract_after_s = 60,
	    .attract_speed = M_PI / 12,
	    .mode = (enum shading_mode)o->mode,
	    .matcap_count = s->set ? matcap_set_count(s->set) : 1,
	};
	struct timespec now;
	int ret;

	k.view = initial_view(o);
	cfg.rest = k.view.orientation;
	clock_gettime(CLOCK_MONOTONIC, &now);
	app_init(&k.app, &cfg, (uint64_t)now.tv_sec * 1000000000ull + (uint64_t)now.tv_nsec);
	ret = kiosk_run(&k);
	for (int i = 0; i < k.input_count; i++)
		k.inputs[i]->destroy(k.inputs[i]);
	log_info("%ld frames drawn", k.frames_drawn);
	return ret;
}

static int run(const struct options *o, struct scene *s, double start_ms)
{
	struct display *d = open_display(o);
	struct renderer *r = NULL;
	int ret = -ENODEV;

	if (!d)
		goto out;
	r = renderer_new(&d->gl, o->shader_dir);
	ret = r ? 0 : -ENOMEM;
	if (!ret)
		ret = renderer_set_mode(r, (enum shading_mode)o->mode, o->ortho);
	if (!ret)
		ret = renderer_set_mesh(r, &s->mesh);
	if (!ret)
		ret = renderer_set_matcap(r, &s->matcap);
	if (ret)
		goto out;
	if (o->output || o->frames > 1) {
		ret = render_frames(o, d, r, start_ms);
		if (!ret && o->output)
			ret = write_output(o, d);
	} else {
		ret = run_live(o, s, d, r);
	}
out:
	renderer_free(r);
	display_free(d);
	return ret;
}

int main(int argc, char **argv)
{
	double start_ms = now_ms();
	struct options opts;
	struct scene scene = {0};
	int ret;

	ret = options_parse(&opts, argc, argv);
	if (ret) {
		options_release(&opts);
		return ret == OPTIONS_CONFIG ? 78 /* EX_CONFIG */ : 2;
	}
	if (opts.help || opts.version) {
		if (opts.help)
			options_usage(stdout);
		else
			printf("matcap-kiosk %s\n", MK_VERSION);
		options_release(&opts);
		return 0;
	}
	static const enum log_level levels[] = {LOG_ERR, LOG_WARN, LOG_INFO, LOG_DEBUG};
	log_set_level(levels[opts.log_level]);
	if (opts.backend == BACKEND_AUTO && !opts.output) {
		/* No display backend yet in this build: render a PNG instead. */
		opts.output = strdup("matcap-kiosk.png");
	}
	if (!opts.output && opts.frames == 1)
		kiosk_block_signals();
	ret = load_model(&opts, opts.output != NULL, &scene.mesh);
	if (!ret)
		ret = load_matcap(&opts, opts.output != NULL, &scene);
	if (!ret)
		ret = run(&opts, &scene, start_ms);
	mesh_release(&scene.mesh);
	image_release(&scene.matcap);
	matcap_set_free(scene.set);
	options_release(&opts);
	return ret ? 1 : 0;
}
