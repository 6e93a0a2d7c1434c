/* No leak, no drift: the live loop (kiosk_run, the very code the kiosk
 * runs) through OSMesa for many frames, driven by a scripted input source
 * instead of buttons:
 *   - a small turn every frame, so that every pass of the loop draws;
 *   - the next matcap every --matcap-every frames (decoded and uploaded);
 *   - every --reload-every frames: the config file rewritten to the next
 *     of four variants (a glTF model, the built-in knot, a missing model,
 *     a config error; the last two must keep the scene), a matcap added
 *     to or removed from the watched folder, and SIGHUP sent to itself;
 *   - SIGTERM to itself after --frames frames: the loop must end cleanly.
 * Resident memory (VmRSS) is read before each reload. After --warmup
 * reloads it may grow by --rss-bound KiB at most.
 *   soak DIR [--frames N] [--matcap-every N] [--reload-every N]
 *            [--warmup N] [--rss-bound KIB] [--size N]
 * Prints one line per reload and a summary; exits 0 when every reload did
 * what its variant asks and the memory stayed within the bound.
 * libOSMesa is opened once more here and never closed, so that valgrind
 * can still name its frames at exit (tests/soak/soak.supp matches them). */
#include "display/display.h"
#include "gltf_write.h"
#include "app/kiosk.h"
#include "app/signals.h"
#include "util/log.h"
#include "scene/mesh/mesh.h"
#include "config/options.h"
#include "render/render.h"
#include "content/content.h"

#include <dlfcn.h>
#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#define MAX_RELOADS 1000
#define VARIANTS    4

struct soak_opts {
	const char *dir;
	long frames, matcap_every, reload_every, warmup, rss_bound_kib;
	int size;
};

struct script {
	struct input_source base; /* first: the loop hands this back */
	struct kiosk *k;
	const struct content *content; /* the kiosk's: a reload swaps what it holds */
	const struct soak_opts *o;
	long last_frame;
	long next_reload;     /* frame */
	double last_reload_s; /* CLOCK_MONOTONIC */
	int reloads;
	long rss_kib[MAX_RELOADS];
	uint32_t knot_vertices; /* on screen at the start: the built-in knot */
	int base_matcaps;
	int failures;
};

static double now_s(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_MONOTONIC, &ts);
	return ts.tv_sec + ts.tv_nsec / 1e9;
}

static long rss_kib(void)
{
	FILE *f = fopen("/proc/self/status", "r");
	char line[256];
	long kib = -1;

	while (f && fgets(line, sizeof(line), f))
		if (sscanf(line, "VmRSS: %ld kB", &kib) == 1)
			break;
	if (f)
		fclose(f);
	return kib;
}

static void path_in(char *out, size_t n, const struct soak_opts *o, const char *name)
{
	snprintf(out, n, "%s/%s", o->dir, name);
}

static int write_text(const char *path, const char *text)
{
	FILE *f = fopen(path, "w");

	if (!f)
		return -errno;
	fputs(text, f);
	return fclose(f) ? -errno : 0;
}

/* The config for reload number i: what it must leave on screen is checked
 * before the next one. */
static void write_variant(struct script *s, int i)
{
	static const char *const text[VARIANTS] = {
	    /* Relative: from kiosk.ini's folder, which is o->dir. */
	    "[scene]\nmode = normal\nmodel = sphere.glb\n",
	    "[scene]\nmode = sem-fragment\n",
	    "[scene]\nmodel = no-such-model.glb\n",
	    "[scene]\nmode = phong\n",
	};
	char path[4096], body[4096];

	snprintf(body, sizeof(body), "%s", text[i % VARIANTS]);
	path_in(path, sizeof(path), s->o, "kiosk.ini");
	if (write_text(path, body)) {
		fprintf(stderr, "soak: cannot write %s\n", path);
		s->failures++;
	}
}

/* Add a matcap on even reloads, take it away on odd ones. */
static void change_folder(const struct script *s, int i)
{
	char path[4096], cmd[8300];

	path_in(path, sizeof(path), s->o, "mc/extra.png");
	if (i % 2 == 0) {
		snprintf(cmd, sizeof(cmd), "cp matcaps/pearl.png '%s'", path);
		if (system(cmd) != 0)
			fprintf(stderr, "soak: %s failed\n", cmd);
	} else {
		unlink(path);
	}
}

/* What reload i-1 (and the folder change before it) must have left. The
 * mesh is told by its vertex count as prepared for this display (a level
 * of detail may have simplified it): the knot's is known from the start,
 * and the sphere's must be another. */
static void check_previous(struct script *s, int i)
{
	const struct content *sc = s->content;
	int v = (i - 1) % VARIANTS;
	bool knot = sc->mesh.vertex_count == s->knot_vertices;
	int matcaps = s->base_matcaps + ((i - 1) % 2 == 0 ? 1 : 0);

	if (i == 0)
		return;
	if (knot != (v != 0) || !sc->mesh.vertex_count) {
		fprintf(stderr, "soak: after reload %d (variant %d) the mesh has %u vertices: %s\n",
			i - 1, v, sc->mesh.vertex_count,
			v ? "the knot's must stay" : "the sphere's must replace the knot's");
		s->failures++;
	}
	if (!sc->set || matcap_set_count(sc->set) != matcaps) {
		fprintf(stderr, "soak: after reload %d the folder shows %d matcaps, not %d\n",
			i - 1, sc->set ? matcap_set_count(sc->set) : 0, matcaps);
		s->failures++;
	}
}

static void reload(struct script *s)
{
	int i = s->reloads;

	check_previous(s, i);
	if (i < MAX_RELOADS)
		s->rss_kib[i] = rss_kib();
	printf("reload %3d  frame %8ld  rss %7ld KiB  variant %d\n", i, kiosk_frames_drawn(s->k),
	       s->rss_kib[i < MAX_RELOADS ? i : MAX_RELOADS - 1], i % VARIANTS);
	fflush(stdout);
	write_variant(s, i);
	change_folder(s, i);
	s->reloads++;
	kill(getpid(), SIGHUP);
}

static int script_read(struct input_source *src, uint64_t now, struct app_event *out, int max)
{
	struct script *s = (struct script *)src;
	long f = kiosk_frames_drawn(s->k);
	enum app_action a = ACTION_TURN_LEFT;

	if (f >= s->o->frames) {
		kill(getpid(), SIGTERM);
		return 0;
	}
	if (f == s->last_frame || max < 2)
		return 0;
	s->last_frame = f;
	/* At least a second apart, so that a folder change settles (half a
	 * second in the loop) before the next reload checks it. */
	if (f >= s->next_reload && now_s() - s->last_reload_s >= 1.0) {
		reload(s);
		s->next_reload = f + s->o->reload_every;
		s->last_reload_s = now_s();
	}
	if (f > 0 && f % s->o->matcap_every == 0)
		a = ACTION_NEXT_MATCAP;
	out[0] = (struct app_event){.time_ns = now, .action = a, .pressed = true};
	out[1] = (struct app_event){.time_ns = now, .action = a, .pressed = false};
	return 2;
}

static uint64_t script_deadline(struct input_source *src)
{
	(void)src;
	return 0; /* always: the loop never sleeps */
}

static void script_destroy(struct input_source *src)
{
	(void)src; /* lives on main's stack */
}

static int prepare_dir(const struct soak_opts *o)
{
	struct gltf_write_opts w = {.index_bytes = 2, .with_normals = 1, .bad_index = -1};
	char path[4096], cmd[3 * 4096 + 64];
	struct mesh m;
	int ret;

	path_in(path, sizeof(path), o, "mc");
	snprintf(cmd, sizeof(cmd), "rm -rf '%s' && mkdir -p '%s' && cp matcaps/*.png '%s'", path,
		 path, path);
	if (system(cmd) != 0)
		return -EIO;
	if (mesh_uv_sphere(&m, 32, 16))
		return -ENOMEM;
	path_in(path, sizeof(path), o, "sphere.glb");
	ret = gltf_write(path, &m, &w) ? -EIO : 0;
	mesh_release(&m);
	path_in(path, sizeof(path), o, "kiosk.ini");
	return ret ? ret : write_text(path, "[scene]\nmode = view\n");
}

static int parse_args(int argc, char **argv, struct soak_opts *o)
{
	*o = (struct soak_opts){NULL, 100000, 100, 10000, 2, 4096, 64};
	if (argc < 2)
		return -EINVAL;
	o->dir = argv[1];
	for (int i = 2; i + 1 < argc; i += 2) {
		long v = strtol(argv[i + 1], NULL, 10);

		if (v <= 0)
			return -EINVAL;
		if (!strcmp(argv[i], "--frames"))
			o->frames = v;
		else if (!strcmp(argv[i], "--matcap-every"))
			o->matcap_every = v;
		else if (!strcmp(argv[i], "--reload-every"))
			o->reload_every = v;
		else if (!strcmp(argv[i], "--warmup"))
			o->warmup = v;
		else if (!strcmp(argv[i], "--rss-bound"))
			o->rss_bound_kib = v;
		else if (!strcmp(argv[i], "--size"))
			o->size = (int)v;
		else
			return -EINVAL;
	}
	return argc % 2 ? -EINVAL : 0;
}

/* Memory after the warm-up: the first reading past it against the largest. */
static int report(const struct script *s, double seconds)
{
	const struct soak_opts *o = s->o;
	int n = s->reloads < MAX_RELOADS ? s->reloads : MAX_RELOADS;
	long first = n > o->warmup ? s->rss_kib[o->warmup] : -1, top = first;
	int failures = s->failures;

	for (int i = (int)o->warmup; i < n; i++)
		top = s->rss_kib[i] > top ? s->rss_kib[i] : top;
	printf("soak: %ld frames in %.1f s (%.0f frames/s), %d reloads, a matcap change every "
	       "%ld frames\n",
	       kiosk_frames_drawn(s->k), seconds, kiosk_frames_drawn(s->k) / seconds, s->reloads,
	       o->matcap_every);
	if (first < 0) {
		printf("soak: too few reloads to judge memory (warm-up %ld)\n", o->warmup);
		failures++;
	} else {
		printf(
		    "soak: RSS after %ld warm-up reloads %ld KiB, highest %ld KiB, growth %ld KiB "
		    "(bound %ld KiB)\n",
		    o->warmup, first, top, top - first, o->rss_bound_kib);
		failures += top - first > o->rss_bound_kib;
	}
	if (kiosk_frames_drawn(s->k) < o->frames) {
		printf("soak: the loop stopped after %ld of %ld frames\n", kiosk_frames_drawn(s->k),
		       o->frames);
		failures++;
	}
	return failures ? 1 : 0;
}

static int run(const struct soak_opts *so, char **kiosk_argv, int kiosk_argc, struct script *s)
{
	struct options o;
	struct content content;
	struct display_config cfg = {.width = so->size, .height = so->size};
	struct display *d = NULL;
	struct renderer *r = NULL;
	struct kiosk_parts parts = {.content = &content, .options = &o, .argv = kiosk_argv};
	struct kiosk *k;
	double start;
	int ret;

	ret = options_parse(&o, kiosk_argc, kiosk_argv);
	if (!ret)
		ret = content_load(&content, &o.content, true);
	if (ret)
		goto out_opts;
	s->base_matcaps = matcap_set_count(content.set);
#ifdef MK_HAVE_OSMESA
	d = display_osmesa_new(&cfg);
#else /* Mesa without OSMesa: the same renders through EGL */
	d = display_egl_new(&cfg);
#endif
	r = d ? renderer_new(&d->gl, NULL) : NULL;
	ret = r ? content_prepare(&content, &o.content, d->width, d->height) : -ENODEV;
	if (!ret)
		ret = content_upload(&content, r);
	if (!ret)
		ret = renderer_set_mode(r, o.content.mode, o.content.ortho);
	if (ret)
		goto out;
	s->knot_vertices = content.mesh.vertex_count;
	s->content = &content;
	parts.display = d;
	parts.renderer = r;
	k = kiosk_new(&parts, 0);
	ret = k ? 0 : -ENOMEM;
	if (ret)
		goto out;
	s->k = k;
	kiosk_add_input(k, &s->base);
	start = now_s();
	ret = kiosk_run(k);
	ret = ret ? ret : report(s, now_s() - start);
	kiosk_free(k);
out:
	renderer_free(r);
	display_free(d);
	content_release(&content);
out_opts:
	options_release(&o);
	return ret;
}

int main(int argc, char **argv)
{
	struct soak_opts o;
	struct script s = {0};
	char ini[4096], mc[4096], size[32];
	char *kiosk_argv[] = {
	    "matcap-kiosk", "--backend", "osmesa", "--size", size, "--config", ini,
	    "--matcap",	    mc,		 "-q",	   NULL};
	void *keep;
	int ret;

	if (parse_args(argc, argv, &o) || (mkdir(o.dir, 0755) && errno != EEXIST)) {
		fprintf(stderr, "usage: soak DIR [--frames N] [--matcap-every N] "
				"[--reload-every N] [--warmup N] [--rss-bound KIB] [--size N]\n");
		return 2;
	}
	path_in(ini, sizeof(ini), &o, "kiosk.ini");
	path_in(mc, sizeof(mc), &o, "mc");
	snprintf(size, sizeof(size), "%dx%d", o.size, o.size);
	s.base = (struct input_source){.name = "soak script",
				       .fd = -1,
				       .read = script_read,
				       .deadline = script_deadline,
				       .destroy = script_destroy};
	s.o = &o;
	s.last_frame = -1;
	s.next_reload = o.reload_every;
	if (prepare_dir(&o)) {
		fprintf(stderr, "soak: cannot prepare %s\n", o.dir);
		return 1;
	}
	log_set_level(LOG_WARN);
	/* Before the GL driver starts its threads, as main() does. */
	signals_block();
	keep = dlopen("libOSMesa.so.8", RTLD_NOW | RTLD_LOCAL);
	ret = run(&o, kiosk_argv, 10, &s);
	(void)keep; /* never closed: see the comment at the top */
	return ret ? 1 : 0;
}
