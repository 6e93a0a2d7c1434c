/* matcap-kiosk: a glTF model shaded with a matcap, fullscreen on DRM/KMS
 * or offscreen. main() wires the pieces; each lives in its own file. */
#include "camera/camera.h"
#include "util/clock.h"
#include "display/display.h"
#include "input/gpio.h"
#include "util/image.h"
#include "input/keyboard.h"
#include "app/kiosk.h"
#include "util/log.h"
#include "app/options.h"
#include "render/render.h"
#include "app/content.h"

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

static double now_ms(void)
{
	return (double)monotonic_ns() / 1e6;
}

/* auto: the display when there is one, else a PNG of the scene (the
 * README's first command on a machine with no screen). */
static struct display *open_display(struct options *o)
{
	struct display_config cfg = {.width = o->size[0],
				     .height = o->size[1],
				     .device = o->device,
				     .connector = o->connector,
				     .mode = o->display_mode,
				     .exit_when_busy = o->on_busy == 1,
				     .kms_api = o->kms_api,
				     .quiet = o->backend == BACKEND_AUTO};
	struct display *d;

	switch (o->backend) {
	case BACKEND_EGL_HEADLESS:
		return display_egl_new(&cfg);
	case BACKEND_OSMESA:
		return display_osmesa_new(&cfg);
	case BACKEND_KMS:
		return display_kms_new(&cfg);
	default:
		d = o->output ? NULL : display_kms_new(&cfg);
		if (d)
			return d;
		if (!o->output) {
			o->output = strdup("matcap-kiosk.png");
			log_info("no display found: drawing the scene into %s", o->output);
		}
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

static int render_frames(const struct options *o, struct display *d, struct renderer *r,
			 double start_ms)
{
	struct view v = content_view(o);
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

/* argv: a reload (SIGHUP) parses the same command line again. */
/* Buttons and keyboards. One that cannot be had is logged and left out;
 * two buttons on one line is a config error. */
static void gpio_config_from(const struct options *o, struct gpio_config *c)
{
	*c = (struct gpio_config){.chip = o->gpio_chip,
				  .active = (enum button_active)o->button_active,
				  .bias = (enum button_bias)o->button_bias,
				  .debounce_ms = o->debounce_ms,
				  .long_press_ms = o->long_press_ms,
				  .repeat_ms = o->repeat_ms};
	for (int i = 0; i < GPIO_BUTTONS; i++)
		c->buttons[i] =
		    (struct gpio_button){.line = o->button_line[i],
					 .press = (enum app_action)o->button_press[i],
					 .long_press = (enum app_action)o->button_long[i]};
}

static int open_inputs(const struct options *o, struct kiosk *k)
{
	struct input_source *in[KIOSK_MAX_INPUTS];
	struct gpio_config gc;
	int n;

	gpio_config_from(o, &gc);
	n = gpio_open_buttons(&gc, in, KIOSK_MAX_INPUTS);
	if (n == -EEXIST)
		return OPTIONS_CONFIG;
	if (n < 0)
		return n;
	n += keyboard_open(o->keyboard, in + n, KIOSK_MAX_INPUTS - n);
	for (int i = 0; i < n; i++)
		kiosk_add_input(k, in[i]);
	return 0;
}

static int run_live(const struct options *o, char **argv, struct content *s, struct display *d,
		    struct renderer *r)
{
	/* The renderer already holds the first matcap and the mode. */
	struct kiosk k = {.display = d,
			  .renderer = r,
			  .scene = s,
			  .opts = o,
			  .argv = argv,
			  .shown_mode = (enum shading_mode)o->mode,
			  .shown_ortho = o->ortho};
	int ret;

	while (argv[k.argc])
		k.argc++;
	kiosk_configure(&k, o, (uint64_t)(now_ms() * 1e6));
	ret = open_inputs(o, &k);
	/* No EGL context (OSMesa), no camera. */
	k.camera = ret ? NULL : camera_feed_new(o, &d->gl, d->gl.caps.egl_display != NULL);
	if (!ret)
		ret = kiosk_run(&k);
	if (o->stats)
		camera_feed_print_stats(k.camera, stdout);
	camera_feed_free(k.camera);
	kiosk_release(&k);
	log_info("%ld frames drawn", k.frames_drawn);
	return ret;
}

static int run(const struct options *o, char **argv, struct content *s, struct display *d,
	       double start_ms)
{
	struct renderer *r = renderer_new(&d->gl, o->shader_dir);
	int ret = r ? 0 : -ENOMEM;

	/* The mesh fitted to this display (subdivided for displacement, then
	 * simplified), as a reload does. The scene's material goes up before
	 * the mode, so its program is the first and only one compiled. */
	if (!ret)
		ret = content_prepare(s, o, d->width, d->height);
	if (!ret)
		ret = content_upload(s, r);
	if (!ret)
		ret = renderer_set_mode(r, (enum shading_mode)o->mode, o->ortho);
	if (ret)
		goto out;
	if (o->output || o->frames > 1) {
		ret = render_frames(o, d, r, start_ms);
		if (!ret && o->output)
			ret = write_output(o, d);
	} else {
		ret = run_live(o, argv, s, d, r);
	}
out:
	renderer_free(r);
	return ret;
}

int main(int argc, char **argv)
{
	double start_ms = now_ms();
	struct options opts;
	struct content scene = {0};
	struct display *display;
	bool live;
	int ret;

	/* The kiosk starts itself again as its camera helper (src/camera/camera.h). */
	if (argc > 0 && strcmp(argv[0], CAMERA_HELPER_NAME) == 0)
		return camera_helper_main(CAMERA_HELPER_FD);

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
	/* Before any thread starts: the live loop reads them from a signalfd. */
	live = !opts.output && opts.frames == 1;
	if (live)
		kiosk_block_signals();
	/* A one-shot render fails fast, before the GPU is touched, when a file
	 * the user named does not load; the kiosk itself falls back to the
	 * built-in model and matcap, and says so. */
	ret = live ? 0 : content_load(&scene, &opts, true);
	display = ret ? NULL : open_display(&opts);
	if (!ret && !display)
		ret = -ENODEV;
	if (!ret && live && opts.output) {
		live = false; /* auto found no display: one PNG instead */
		kiosk_unblock_signals();
	}
	if (!ret && !scene.mesh.index_count)
		ret = content_load(&scene, &opts, false);
	if (!ret)
		ret = run(&opts, argv, &scene, display, start_ms);
	display_free(display);
	content_release(&scene);
	options_release(&opts);
	return ret == OPTIONS_CONFIG ? 78 : ret ? 1 : 0;
}
