/* matcap-kiosk: a glTF model shaded with a matcap, fullscreen on DRM/KMS
 * or offscreen. main() wires the pieces; each lives in its own file. */
#include "camera/camera.h"
#include "util/clock.h"
#include "display/display.h"
#include "util/image.h"
#include "app/kiosk.h"
#include "app/preview.h"
#include "app/signals.h"
#include "util/log.h"
#include "config/exit_codes.h"
#include "config/options.h"
#include "render/render.h"
#include "content/content.h"
#include "ops/import.h"
#include "ops/status.h"
#include "ops/check.h"
#include "render/poster.h"
#include "render/render_scale.h"
#include "scene/mesh/mesh_cache.h"
#include "scene/text/caption_wrap.h"

#include <errno.h>
#include <malloc.h>
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
static struct display *open_display(struct options *o, int *err)
{
	struct display_config cfg = o->display;
	struct display *d;

	cfg.quiet = o->backend == BACKEND_AUTO;
	switch (o->backend) {
	case BACKEND_EGL_HEADLESS:
		return display_egl_new(&cfg);
	case BACKEND_OSMESA:
		return display_osmesa_new(&cfg);
	case BACKEND_KMS:
		return display_kms_open(&cfg, err);
	default:
		d = o->output ? NULL : display_kms_open(&cfg, err);
		if (d)
			return d;
		if (!o->output) {
			o->output = strdup("matcap-kiosk.png");
			log_info("no display found: drawing the scene into %s", o->output);
		}
#ifdef MK_HAVE_OSMESA
		return display_osmesa_new(&cfg);
#else /* Mesa 25.1 and later: no OSMesa, the same through EGL */
		return display_egl_new(&cfg);
#endif
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

/* One frame on every output ([display] outputs; one elsewhere), each as
 * its [output.NAME] shows it, or all as --as-output's. */
static int draw_still(const struct options *o, struct display *d, struct renderer *r,
		      struct render_scale *scale, const struct view *frame)
{
	int n = d->select_output ? d->outputs : 1, ret = 0, shown = 0;

	for (int i = 0; i < n && !ret; i++) {
		const struct output_view *ov;
		struct view v = *frame;
		int w, h;

		if (d->select_output && d->select_output(d, i))
			continue;
		ov = output_view_find(&o->outputs, o->as_output ? o->as_output : d->output_name);
		output_view_apply(ov, &v);
		if ((ret = d->begin_frame(d)))
			break;
		render_scale_begin(scale, d->plane_scaled, d->width, d->height, &w, &h);
		renderer_draw(r, &v, w, h);
		render_scale_end(scale);
		/* Full-resolution overlays draw here, as in the live loop. */
		if (!ov || ov->caption)
			renderer_draw_caption(r, &v, 0, d->width, d->height);
		ret = d->present(d);
		shown++;
	}
	return ret ? ret : shown ? 0 : -EAGAIN;
}

static int render_frames(const struct options *o, const struct content *s, struct display *d,
			 struct renderer *r, double start_ms)
{
	const struct content_config *c = content_settings(s, &o->content);
	struct view v = content_view(c);
	double *times = calloc((size_t)o->frames, sizeof(double));
	struct render_scale *scale =
	    render_scale_new(&d->gl, o->display.render_scale, d->samples, o->shader_dir);
	double first = 0;
	int ret = 0, stop;

	if (!times || !scale) {
		free(times);
		render_scale_free(scale);
		return -ENOMEM;
	}
	/* [frame] zoom: the start view's, over the fit's. */
	v.zoom = (float)(s->zoom * (c->frame.zoom > 0 ? c->frame.zoom : 1.0));
	content_place_view(s, &v);
	/* --stop, --at: that moment, and its stop's caption. */
	if ((o->preview_stop > 0 || o->preview_at >= 0) &&
	    (ret = preview_moment(o, s, c, &v, &stop)) == 0)
		renderer_show_stop(r, stop);
	if (o->hotspot > 0)
		ret = content_show_hotspot(s, c, o->hotspot, r, &v);
	for (int i = 0; i < o->frames && !ret; i++) {
		double t = now_ms();

		ret = draw_still(o, d, r, scale, &v);
		times[i] = now_ms() - t;
		if (i == 0)
			first = now_ms() - start_ms;
	}
	if (!ret && o->stats)
		print_stats(times, o->frames, first);
	render_scale_free(scale);
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
/* posters: frames flipped before the kiosk took over, counted with its
 * own (each went to the screen by a flip). */
static int run_live(const struct options *o, char **argv, struct content *s, struct display *d,
		    struct renderer *r, int posters)
{
	struct kiosk_parts parts = {.display = d,
				    .renderer = r,
				    .content = s,
				    .options = o,
				    .argv = argv,
				    /* No EGL context (OSMesa), no camera. */
				    .camera_possible = d->gl.caps.egl_display != NULL};
	struct kiosk *k = kiosk_new(&parts, monotonic_ns());
	int ret = k ? kiosk_open_devices(k) : -ENOMEM;

	if (!ret)
		ret = kiosk_run(k);
	if (k && o->stats)
		kiosk_print_stats(k, stdout);
	if (k)
		log_info("%ld frames drawn", kiosk_frames_drawn(k) + posters);
	kiosk_free(k);
	return ret;
}

static int run(const struct options *o, char **argv, struct content *s, struct display *d,
	       double start_ms, int posters)
{
	struct renderer *r = renderer_new(&d->gl, o->shader_dir);
	int ret = r ? 0 : -ENOMEM;

	/* The mesh fitted to this display (subdivided for displacement, then
	 * simplified), as a reload does. The scene's material goes up before
	 * the mode, so its program is the first and only one compiled. */
	if (!ret)
		ret = content_prepare(s, &o->content, d->width, d->height);
	if (!ret)
		ret = content_upload(s, r);
	/* [scene] variant (--variant): its materials; none named, the file's. */
	if (!ret)
		renderer_show_variant(
		    r, content_variant_find(s, content_settings(s, &o->content)->variant));
	if (!ret)
		ret = renderer_set_mode(r, o->content.mode, o->content.ortho);
	if (ret)
		goto out;
	if (o->output || o->frames > 1) {
		ret = render_frames(o, s, d, r, start_ms);
		if (!ret && o->output)
			ret = write_output(o, d);
	} else {
		ret = run_live(o, argv, s, d, r, posters);
	}
out:
	renderer_free(r);
	return ret;
}

/* The exit status (config/exit_codes.h): 2 for a bad command line, 78 for
 * a bad config file; for a display that does not open, why: 77
 * forbidden, 75 busy, 69 absent; 1 when a model, image or display fails
 * otherwise. --check-config says 66 for a named file that is missing or
 * broken.
 *
 * -EEXIST comes only from kiosk_open_devices: two buttons on one line,
 * which the settings could not tell (GPIO17 and 17), a config error. The
 * display's reasons come from display_kms_open, wrapped by show(). */
static enum exit_code exit_code(int ret)
{
	if (ret == -EEXIST)
		return EXIT_CODE_CONFIG;
	return ret ? EXIT_CODE_FAILED : EXIT_CODE_OK;
}

/* Only the display's reasons are told apart by the exit status (a model
 * that is missing or unreadable stays 1). */
static enum exit_code display_failed(int err)
{
	enum exit_code code = EXIT_CODE_FAILED;
	const char *why = "it failed (above)";

	if (err == -EACCES || err == -EPERM)
		code = EXIT_CODE_NOPERM, why = "forbidden (the node's permissions)";
	else if (err == -EBUSY)
		code = EXIT_CODE_TEMPFAIL, why = "busy (another program is DRM master)";
	else if (err == -ENODEV || err == -ENOENT)
		code = EXIT_CODE_UNAVAILABLE, why = "absent (no such display)";
	log_err("the display cannot be opened: %s; exit status %d", why, (int)code);
	return code;
}

static bool is_live(const struct options *o)
{
	return !o->output && o->frames == 1;
}

/* A one-shot render fails fast, before the GPU is touched, when a file
 * the user named does not load. The live kiosk blocks its signals instead,
 * before any thread starts (the GL driver's): the loop reads them from a
 * signalfd. */
static int before_display(const struct options *o, struct content *content)
{
	if (!is_live(o))
		return content_load(content, &o->content, true);
	import_clean_stale(); /* a half copy an import cut short left */
	signals_block();
	return 0;
}

/* When auto found no display, the kiosk draws one PNG instead, with no
 * loop for the signals. The kiosk falls back to the built-in model and
 * matcap, and says so. */
static int after_display(const struct options *o, bool was_live, struct content *content)
{
	if (was_live && !is_live(o))
		signals_unblock();
	return content->mesh.index_count ? 0 : content_load(content, &o->content, false);
}

/* Something on the screen at once, before the model loads: the poster,
 * or the background. A failure here is logged and passed over. */
/* The background the model will have ([display] background), for the
 * poster; a plain colour where it cannot be drawn. */
static struct background *poster_background(const struct options *o, struct display *d)
{
	struct background_spec spec;
	struct image img;
	struct background *bg;

	content_load_background(&o->content, false, &spec, &img);
	bg = background_new(&d->gl, &spec, &img);
	image_release(&img);
	if (!bg) {
		background_spec_default(&spec);
		bg = background_new(&d->gl, &spec, NULL);
	}
	return bg;
}

static int show_poster(const struct options *o, struct display *d)
{
	struct image img = {0};
	bool have = o->poster && *o->poster && image_load(o->poster, &img) == 0;
	struct background *bg = NULL;
	int shown = 0;

	if (o->poster && *o->poster && !have)
		log_warn("[display] poster %s does not load: the background instead", o->poster);
	if (d->begin_frame(d) == 0 && (bg = poster_background(o, d))) {
		if (poster_draw(&d->gl, have ? &img : NULL, d->width, d->height,
				o->content.rotation, bg))
			log_warn("[display] poster %s cannot be drawn: the background instead",
				 o->poster);
		if (d->present(d) == 0 && ++shown)
			log_info("poster: %s on the screen while the model loads",
				 have ? o->poster : "the background");
	}
	background_free(bg);
	image_release(&img);
	return shown;
}

static int show(struct options *o, char **argv, enum exit_code *display_code)
{
	double start_ms = now_ms();
	bool live = is_live(o);
	struct content content = {0};
	struct display *display = NULL;
	int posters = 0, err = -ENODEV;
	int ret;

	/* Only the live kiosk plays an animation; a still is drawn as it was. */
	o->content.anim_live = live && o->content.anim_time < 0;
	ret = before_display(o, &content);

	if (!ret && !(display = open_display(o, &err))) {
		*display_code = display_failed(err);
		ret = -ENODEV;
	}
	if (!ret && live && is_live(o))
		posters = show_poster(o, display);
	o->content.anim_live = is_live(o) && o->content.anim_time < 0;
	o->content.crash_memory = is_live(o);
	o->content.coarse_first = is_live(o);
	if (!ret)
		ret = after_display(o, live, &content);
	if (!ret)
		ret = run(o, argv, &content, display, start_ms, posters);
	display_free(display);
	content_release(&content);
	return ret;
}

/* The settings did not read (each error is above); --check-config ends
 * with its verdict, as it does when they read. */
static enum exit_code parse_failed(enum options_status status, int argc, char **argv)
{
	const char *name = "the command line";
	bool check = false;

	for (int i = 1; i < argc && status == OPTIONS_CONFIG; i++) {
		check |= !strcmp(argv[i], "--check-config");
		if ((!strcmp(argv[i], "--config") || !strcmp(argv[i], "-C")) && i + 1 < argc)
			name = argv[i + 1];
		else if (!strncmp(argv[i], "--config=", 9))
			name = argv[i] + 9;
	}
	if (check)
		log_err("%s: the settings are not valid (the errors above)", name);
	return status == OPTIONS_CONFIG ? EXIT_CODE_CONFIG : EXIT_CODE_USAGE;
}

/* The subcommands that talk to a kiosk or look after its files. */
static enum exit_code tool(struct options *o)
{
	int ret;

	if (o->status)
		return status_client_run(stdout) ? EXIT_CODE_FAILED : EXIT_CODE_OK;
	if (o->check_config)
		return (enum exit_code)check_config_run(o, stdout);
	ret = import_run(o);
	return ret == -EINVAL ? EXIT_CODE_CONFIG : exit_code(ret);
}

static enum exit_code show_exit_code(struct options *o, char **argv)
{
	enum exit_code display_code = EXIT_CODE_OK;
	int ret = show(o, argv, &display_code);

	return display_code != EXIT_CODE_OK ? display_code : exit_code(ret);
}

static enum exit_code start(struct options *o, char **argv)
{
	if (o->help)
		options_usage(stdout);
	else if (o->version)
		printf("matcap-kiosk %s\n", MK_VERSION);
	else if (o->status || o->check_config || o->import)
		return tool(o);
	else
		return show_exit_code(o, argv);
	return EXIT_CODE_OK;
}

/* Mesa maps its shader cache's index whole: on a full cache file system
 * a page of it cannot be backed, and the kiosk dies of SIGBUS in the
 * driver. So the cache is turned off before any context exists, and any
 * thread. */
static void guard_shader_cache(void)
{
	const char *mesa = getenv("MESA_SHADER_CACHE_DIR");
	char dir[4096];
	uint64_t left = 0;

	if (mesa && *mesa)
		snprintf(dir, sizeof(dir), "%s", mesa);
	else if (mesh_cache_dir(dir, sizeof(dir)))
		return;
	if (!mesh_cache_dir_full(dir, &left))
		return;
	setenv("MESA_SHADER_CACHE_DISABLE", "true", 1);
	setenv("MESA_GLSL_CACHE_DISABLE", "true", 1); /* its name before Mesa 23 */
	log_warn("%s: %llu KiB free, under 16 MiB: Mesa's shader cache is off "
		 "(MESA_SHADER_CACHE_DISABLE), so a full disk cannot stop the kiosk",
		 dir, (unsigned long long)(left >> 10));
}

int main(int argc, char **argv)
{
	struct options opts;
	enum options_status status;
	enum exit_code ret;

	/* The kiosk starts itself again as its camera helper (src/camera/camera.h). */
	if (argc > 0 && strcmp(argv[0], CAMERA_HELPER_NAME) == 0)
		return camera_helper_main(CAMERA_HELPER_FD);
	/* An array of 1 MiB or more is mapped for itself and unmapped when
	 * freed. glibc's moving threshold would put those under the largest
	 * one freed so far (a model file's 28 MB) on the heap instead, where
	 * a cold start's many large arrays in turn (the file, the parse, the
	 * level of detail's clusters on several threads' arenas) held 10 MB
	 * more at the peak (issue 34), and a kiosk switching models for
	 * months gives back what a model freed. */
	mallopt(M_MMAP_THRESHOLD, 1 << 20);
	status = options_parse(&opts, argc, argv);
	log_set_level(opts.log_level);
	guard_shader_cache();
	caption_wrap_init(); /* before the worker's thread wraps a caption */
	ret = status == OPTIONS_OK ? start(&opts, argv) : parse_failed(status, argc, argv);
	options_release(&opts);
	return ret;
}
