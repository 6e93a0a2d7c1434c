/* Speed against error: every quality setting's cost (median ms per frame)
 * and error (against the same scene at the highest quality), through the
 * real renderer objects. For each scene the settings change one at a time
 * from the defaults: the mapping mode, the precision, the mesh's level of
 * detail, the matcap's size, supersampling (the frame is drawn at 2x or
 * 4x the size and box-filtered down on the CPU, which the time leaves
 * out: on a GPU that is one more textured pass) and multisampling
 * ([display] antialias, on EGL headless displays beside the others: OSMesa
 * has none; the time includes the resolve). Writes OUTDIR/speed-error.md (the tables),
 * OUTDIR/speed-error.dat and -front.dat (for tests/bench/report/speed-error.gp).
 * Figures are printed, never asserted.
 *
 * usage: bench_quality OUTDIR SCRATCH [--frames N] [--size WxH]
 *                      [--backend osmesa|egl-headless] [--only TEXT]
 * (SCRATCH gets the detail map it draws with). */
#include "render/bake.h"
#include "bench_quality.h"
#include "display/display.h"
#include "scene/mesh/lod.h"
#include "util/log.h"
#include "maps.h"
#include "scene/gltf/gltf.h"
#include "scene/mesh/material.h"
#include "scene/mesh/mesh.h"
#include "config/options.h"
#include "render/render.h"
#include "render/shading.h"

#include "bench_clock.h"

#include <EGL/egl.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

static const double lod_steps[] = {0, 0.5, 1, 2, 4, 8};
static const int matcap_sizes[] = {64, 128, 256, 512, 1024};
static const int ss_factors[] = {1, 2, 4};

const struct look looks[LOOKS] = {
    {"built-in knot (16k), view", KNOT_16K, SHADING_VIEW, SHADING_NORMAL, false, false, false, 0},
    {"knot 100k, view", KNOT_100K, SHADING_VIEW, SHADING_NORMAL, false, false, false, 0},
    {"knot 1M, view", KNOT_1M, SHADING_VIEW, SHADING_NORMAL, false, false, false, 0},
    {"knot 100k, sem", KNOT_100K, SHADING_SEM_FRAGMENT, SHADING_SEM_VERTEX, false, false, false, 0},
    {"knot 100k, iridescence", KNOT_100K, SHADING_VIEW, SHADING_NORMAL, true, false, false, 0},
    {"knot 100k, detail map", KNOT_100K, SHADING_VIEW, SHADING_NORMAL, false, true, false, 0},
    {"knot 100k, lit", KNOT_100K, SHADING_VIEW, SHADING_VIEW, false, false, true, 0},
    /* Small on screen: the whole matcap disk in a few pixels, where an
     * unfiltered matcap aliases. */
    {"knot 100k, view, 128 px", KNOT_100K, SHADING_VIEW, SHADING_NORMAL, false, false, false, 128},
    {"knot 100k, sem, 128 px", KNOT_100K, SHADING_SEM_FRAGMENT, SHADING_SEM_VERTEX, false, false,
     false, 128},
    {"CAD engine 121k (seams, hard edges), view", ENGINE, SHADING_VIEW, SHADING_NORMAL, false,
     false, false, 0},
};

static void read_load(char *out, size_t size)
{
	FILE *f = fopen("/proc/loadavg", "r");

	snprintf(out, size, "unknown");
	if (f && fgets(out, (int)size, f))
		out[strcspn(out, " ")] = '\0'; /* the last minute's */
	if (f)
		fclose(f);
}

static const int msaa_asked[] = {DISPLAY_AA_OFF, DISPLAY_AA_2, DISPLAY_AA_4, DISPLAY_AA_8};

/* Which display draws s: by its supersampling, or EGL's by its samples. */
static int display_of(const struct bench *b, const struct setting *s)
{
	if (s->msaa == 1)
		return 3;
	for (int k = 4; s->msaa && k < DISPLAYS; k++)
		if (b->display[k] && b->display[k]->samples == s->msaa)
			return k;
	return s->ss == 4 ? 2 : s->ss == 2 ? 1 : 0;
}

static int matcap_index(int size)
{
	for (int i = 0; i < 5; i++)
		if (matcap_sizes[i] == size)
			return i;
	return 2;
}

static struct setting *add(struct bench *b, int l, const char *label)
{
	struct setting *s = &b->settings[l][b->count[l]++];

	*s = (struct setting){.same_as = -1,
			      .mode = looks[l].mode,
			      .highp = b->highp_default,
			      .lod = b->lod_default,
			      .matcap = DEFAULT_MATCAP,
			      .filter = b->filter_default,
			      .format = b->format_default,
			      .ss = 1};
	snprintf(s->label, sizeof(s->label), "%s", label);
	return s;
}

/* The reference first (every other setting is measured against it), then
 * the defaults, then each knob alone. */
static void plan(struct bench *b, int l)
{
	const struct look *lk = &looks[l];
	struct setting *s = add(b, l, "reference");
	char label[40];

	s->is_reference = true, s->highp = true, s->lod = 0, s->matcap = 1024, s->ss = 4;
	s->filter = MATCAP_FILTER_MIPMAP, s->format = VERTEX_FLOAT32;
	add(b, l, "defaults")->is_default = true;
	add(b, l, b->format_default == VERTEX_COMPACT ? "float32 vertices" : "int16 vertices")
	    ->format = b->format_default == VERTEX_COMPACT ? VERTEX_FLOAT32 : VERTEX_COMPACT;
	if (!lk->lit && b->filter_default != MATCAP_FILTER_MIPMAP)
		add(b, l, "matcap mipmapped")->filter = MATCAP_FILTER_MIPMAP;
	if (!lk->lit && b->filter_default != MATCAP_FILTER_LINEAR)
		add(b, l, "matcap unfiltered")->filter = MATCAP_FILTER_LINEAR;
	if (lk->cheaper != lk->mode) {
		snprintf(label, sizeof(label), "mode %s", shading_mode_name(lk->cheaper));
		add(b, l, label)->mode = lk->cheaper;
	}
	add(b, l, b->highp_default ? "mediump" : "highp")->highp = !b->highp_default;
	for (size_t i = 0; i < sizeof(lod_steps) / sizeof(lod_steps[0]); i++) {
		if (lod_steps[i] == b->lod_default)
			continue;
		snprintf(label, sizeof(label), lod_steps[i] ? "lod %g px" : "lod off",
			 lod_steps[i]);
		add(b, l, label)->lod = lod_steps[i];
	}
	for (int i = 0; i < 5 && !lk->lit; i++) {
		if (matcap_sizes[i] == DEFAULT_MATCAP)
			continue;
		snprintf(label, sizeof(label), "matcap %d", matcap_sizes[i]);
		add(b, l, label)->matcap = matcap_sizes[i];
	}
	for (int i = 1; i < 3; i++) {
		snprintf(label, sizeof(label), "supersample %dx", ss_factors[i]);
		add(b, l, label)->ss = ss_factors[i];
	}
	/* antialias = 2, 4, 8: one row for each count of samples the GPU
	 * gives (it gives its most for more), after EGL headless without,
	 * the cost's baseline (OSMesa's context is another). */
	if (b->display[3])
		add(b, l, "egl-headless, antialias off")->msaa = 1;
	for (int k = 4; k < DISPLAYS; k++) {
		int got = b->display[k] ? b->display[k]->samples : 0;

		if (!got || (k > 4 && b->display[k - 1] && b->display[k - 1]->samples == got))
			continue;
		snprintf(label, sizeof(label), "antialias %d (msaa)", got);
		add(b, l, label)->msaa = got;
	}
}

static int make_model(enum model m, struct mesh *out)
{
	static const int grid[3][2] = {{256, 32}, {1024, 49}, {4096, 122}};

	if (m == ENGINE)
		return gltf_load(ENGINE_GLB, out);
	return mesh_torus_knot(out, grid[m][0], grid[m][1]);
}

static int copy_mesh(const struct mesh *src, struct mesh *dst)
{
	int ret = mesh_alloc(dst, src->vertex_count, src->index_count, src->uvs != NULL);

	if (!ret && src->tangents)
		ret = mesh_alloc_tangents(dst);
	if (ret)
		return ret;
	memcpy(dst->positions, src->positions, (size_t)src->vertex_count * 12);
	memcpy(dst->normals, src->normals, (size_t)src->vertex_count * 12);
	if (src->uvs)
		memcpy(dst->uvs, src->uvs, (size_t)src->vertex_count * 8);
	if (src->tangents)
		memcpy(dst->tangents, src->tangents, (size_t)src->vertex_count * 16);
	memcpy(dst->indices, src->indices, (size_t)src->index_count * 4);
	return 0;
}

/* The kiosk's resting view (src/content/content.c with the default yaw and pitch). */
static struct view resting_view(void)
{
	struct view v = {.background = {0.06f, 0.06f, 0.07f}};

	v.orientation = quat_multiply(quat_from_axis_angle(1, 0, 0, 20.0 * M_PI / 180),
				      quat_from_axis_angle(0, 1, 0, -30.0 * M_PI / 180));
	return v;
}

/* A box filter of factor x factor pixels. */
static int downsample(const struct image *big, int factor, struct image *out)
{
	int ret = image_alloc(out, big->width / factor, big->height / factor);

	for (int y = 0; !ret && y < out->height; y++)
		for (int x = 0; x < out->width; x++)
			for (int c = 0; c < 4; c++) {
				int sum = 0;

				for (int j = 0; j < factor; j++)
					for (int i = 0; i < factor; i++)
						sum += big->rgba[(((size_t)y * factor + j) *
								      big->width +
								  (size_t)x * factor + i) *
								     4 +
								 c];
				out->rgba[((size_t)y * out->width + x) * 4 + c] =
				    (uint8_t)((sum + factor * factor / 2) / (factor * factor));
			}
	return ret;
}

/* PSNR and the share of pixels off by more than OFF_TOL, over the pixels
 * where either image shows the model (not the background). */
static void image_error(const struct image *a, const struct image *ref, const uint8_t bg[3],
			double *psnr, double *off)
{
	double se = 0.0;
	long n = 0, bad = 0;

	for (size_t p = 0; p < (size_t)a->width * (size_t)a->height; p++) {
		const uint8_t *x = a->rgba + p * 4, *y = ref->rgba + p * 4;
		int worst = 0;

		if (!memcmp(x, bg, 3) && !memcmp(y, bg, 3))
			continue;
		for (int c = 0; c < 3; c++) {
			int d = abs((int)x[c] - (int)y[c]);

			se += (double)d * d;
			worst = d > worst ? d : worst;
		}
		n++;
		bad += worst > OFF_TOL;
	}
	*psnr = se > 0.0 ? 10.0 * log10(255.0 * 255.0 * 3.0 * (double)n / se) : INFINITY;
	*off = n ? (double)bad / (double)n : 0.0;
}

/* Draw one setting WARMUP + n times (the first compile the shaders and
 * settle the caches; not counted), adding the n times to s->times; with
 * frame set, read the last frame back at the display's size. */
static int measure(struct bench *b, const struct look *lk, const struct material *mat,
		   const struct mesh *mesh, struct setting *s, int n, struct image *frame)
{
	int k = display_of(b, s);
	struct display *d = b->display[k];
	struct renderer *r = b->renderer[k];
	struct view v = resting_view();
	struct renderer_stats stats;
	struct image big = {0};
	/* After another display (another context and frame size), llvmpipe
	 * takes a few frames to settle: more of them are not counted. */
	int warmup = k == b->last_display ? WARMUP : WARMUP_SWITCH;

	int w = lk->small ? lk->small * s->ss : d->width;
	int h = lk->small ? lk->small * s->ss : d->height;
	int ret;

	/* OSMesa's displays and EGL's share Mesa's one current context per
	 * thread, but EGL keeps its own record of it: once OSMesa has drawn,
	 * EGL would take its context for current still. Released here, EGL's
	 * begin_frame makes its own current again. */
	if (k != b->last_display && eglGetCurrentContext() != EGL_NO_CONTEXT)
		eglMakeCurrent(eglGetCurrentDisplay(), EGL_NO_SURFACE, EGL_NO_SURFACE,
			       EGL_NO_CONTEXT);
	renderer_set_vertex_format(r, s->format);
	renderer_set_matcap_filter(r, s->filter);
	ret = d->begin_frame(d);
	if (!ret)
		ret = renderer_set_material(r, mat);
	if (!ret)
		ret = renderer_set_mesh(r, mesh);
	if (!ret)
		ret = renderer_set_matcap(r, &b->matcap[matcap_index(s->matcap)]);
	if (!ret)
		ret = renderer_set_precision(r, s->highp);
	if (!ret)
		ret = renderer_set_mode(r, s->mode, false);
	renderer_get_stats(r, &stats);
	s->vertex_bytes = stats.vertex_bytes;
	b->last_display = k;
	for (int i = -warmup; i < n && !ret; i++) {
		double t = bench_now_ms();

		ret = d->begin_frame(d);
		/* A small scene is drawn in the frame's corner (the viewport):
		 * the rest is background, which the error leaves out. */
		renderer_draw(r, &v, w, h);
		if (!ret)
			ret = d->present(d);
		if (i >= 0 && s->timed < MAX_FRAMES)
			s->times[s->timed++] = bench_now_ms() - t;
	}
	if (!ret && frame)
		ret = d->read_frame(d, &big);
	if (!ret && frame)
		ret = downsample(&big, s->ss, frame);
	image_release(&big);
	return ret;
}

static void summarize_times(struct setting *s)
{
	qsort(s->times, (size_t)s->timed, sizeof(double), bench_compare_double);
	s->ms = s->timed ? s->times[s->timed / 2] : 0.0;
	s->p90 = s->timed ? s->times[(s->timed * 9) / 10] : 0.0;
}

static int load_material(struct bench *b, const struct look *lk, const struct mesh *mesh,
			 struct material *mat)
{
	struct material_config cfg;
	int ret;

	material_config_defaults(&cfg);
	cfg.iridescence = lk->iridescence ? MATERIAL_ON : MATERIAL_OFF;
	cfg.detail = lk->detail ? MATERIAL_ON : MATERIAL_OFF;
	cfg.detail_map = lk->detail ? b->detail_path : NULL;
	cfg.lit = lk->lit ? LIT_ON : LIT_OFF;
	ret = material_load(mat, &cfg, mesh, true);
	cfg.detail_map = NULL; /* not ours to free */
	material_config_release(&cfg);
	return ret;
}

/* A setting that draws exactly what an earlier one drew (a level of
 * detail that leaves this model whole, say) takes its figures: measuring
 * it twice would only show the timing noise. */
static bool same_drawing(const struct look *lk, const struct setting *a, const struct setting *b)
{
	return a->triangles == b->triangles && a->mode == b->mode && a->highp == b->highp &&
	       (lk->lit || (a->matcap == b->matcap && a->mipmapped == b->mipmapped)) &&
	       a->ss == b->ss && a->msaa == b->msaa && a->format == b->format;
}

int bench_rounds_frames(const struct bench *b)
{
	return b->frames / ROUNDS > 1 ? b->frames / ROUNDS : 2;
}

/* Each level of detail a scene's settings ask for, prepared once as the
 * kiosk does (tangents, then LOD); mesh_of[i]: setting i's. */
static int prepare_meshes(struct bench *b, int l, const struct mesh *base,
			  const struct material *mat, struct mesh *m, int *mesh_of)
{
	const struct setting *s = b->settings[l];
	int meshes = 0, ret = 0;

	for (int i = 0; i < b->count[l] && !ret; i++) {
		mesh_of[i] = -1;
		for (int k = 0; k < i && mesh_of[i] < 0; k++)
			if (s[k].lod == s[i].lod)
				mesh_of[i] = mesh_of[k];
		if (mesh_of[i] >= 0)
			continue;
		mesh_of[i] = meshes;
		ret = copy_mesh(base, &m[meshes]);
		if (!ret)
			ret = material_prepare_mesh(mat, &m[meshes], b->width, b->height);
		if (!ret)
			ret = lod_prepare_mesh(&m[meshes], s[i].lod, b->width, b->height, NULL);
		meshes++;
	}
	return ret;
}

/* One scene: the settings are drawn in ROUNDS interleaved rounds, so that
 * a change in the machine's load falls on all of them alike; the errors
 * come from the first round's frames. */
static int run_look(struct bench *b, int l)
{
	const struct look *lk = &looks[l];
	const uint8_t bg[3] = {15, 15, 18}; /* 0.06, 0.06, 0.07 */
	struct setting *s = b->settings[l];
	int n = b->count[l], mesh_of[MAX_SETTINGS];
	struct mesh base = {0}, m[MAX_SETTINGS];
	struct image frames[MAX_SETTINGS];
	struct material mat = {0};
	int ret;

	memset(m, 0, sizeof(m));
	memset(frames, 0, sizeof(frames));
	ret = make_model(lk->model, &base);
	if (!ret)
		ret = load_material(b, lk, &base, &mat);
	if (!ret)
		ret = prepare_meshes(b, l, &base, &mat, m, mesh_of);
	for (int i = 0; i < n && !ret; i++) {
		int w = (lk->small ? lk->small : b->width) * s[i].ss;
		int h = (lk->small ? lk->small : b->height) * s[i].ss;

		s[i].triangles = m[mesh_of[i]].index_count / 3;
		/* auto draws exactly as one of the forced filters */
		s[i].mipmapped = matcap_filter_mipmaps(s[i].filter, s[i].matcap, w, h);
		for (int k = 0; k < i && s[i].same_as < 0; k++)
			if (s[k].same_as < 0 && same_drawing(lk, &s[k], &s[i]))
				s[i].same_as = k;
	}
	/* Each round by display, the reference (4x) after the plain ones. */
	for (int round = 0; round < ROUNDS && !ret; round++)
		for (int k = 0; k < DISPLAYS; k++)
			for (int i = 0; i < n && !ret; i++)
				if (s[i].same_as < 0 && display_of(b, &s[i]) == k)
					ret = measure(b, lk, &mat, &m[mesh_of[i]], &s[i],
						      bench_rounds_frames(b),
						      round ? NULL : &frames[i]);
	for (int i = 0; i < n && !ret; i++) {
		int from = s[i].same_as >= 0 ? s[i].same_as : i;

		if (from == i)
			summarize_times(&s[i]);
		/* frames[0] is the reference's */
		image_error(&frames[from], &frames[0], bg, &s[i].psnr, &s[i].off);
		s[i].ms = s[from].ms, s[i].p90 = s[from].p90;
		s[i].vertex_bytes = s[from].vertex_bytes;
		fprintf(stderr, "  %s / %s: %.1f ms, %.1f dB\n", lk->name, s[i].label, s[i].ms,
			s[i].psnr);
	}
	for (int i = 0; i < MAX_SETTINGS; i++) {
		image_release(&frames[i]);
		mesh_release(&m[i]);
	}
	material_release(&mat);
	mesh_release(&base);
	return ret;
}

/* On the front: no other setting is as accurate (within PSNR_TIE) and
 * faster (by more than NOISE), or more accurate and as fast (within NOISE).
 * Differences inside the noise of either measure decide nothing. */
static void mark_front(struct setting *s, int n)
{
	for (int i = 0; i < n; i++) {
		s[i].front = true;
		for (int j = 0; j < n && s[i].front; j++) {
			bool faster = s[j].ms < s[i].ms * (1.0 - NOISE);
			bool as_fast = s[j].ms < s[i].ms * (1.0 + NOISE);
			bool better = s[j].psnr > s[i].psnr + PSNR_TIE;
			bool as_good = s[j].psnr > s[i].psnr - PSNR_TIE;

			if (j != i && ((as_good && faster) || (better && as_fast)))
				s[i].front = false;
		}
	}
}

static int parse_args(struct bench *b, int argc, char **argv)
{
	struct options o;
	char *none[] = {argv[0], NULL};

	if (options_parse(&o, 1, none))
		return -EINVAL;
	b->lod_default = o.content.lod_pixels;
	options_release(&o);
	b->width = 1280, b->height = 720, b->frames = 15;
	if (argc < 3)
		return -EINVAL;
	b->out = argv[1];
	b->scratch = argv[2];
	for (int i = 3; i + 1 < argc; i += 2) {
		if (!strcmp(argv[i], "--frames"))
			b->frames = atoi(argv[i + 1]);
		else if (!strcmp(argv[i], "--size") &&
			 sscanf(argv[i + 1], "%dx%d", &b->width, &b->height) == 2)
			continue;
		else if (!strcmp(argv[i], "--only"))
			b->only = argv[i + 1];
		else if (!strcmp(argv[i], "--backend"))
			b->egl = !strcmp(argv[i + 1], "egl-headless");
		else
			return -EINVAL;
	}
	return b->frames > 0 && b->width > 0 && b->height > 0 ? 0 : -EINVAL;
}

static int open_displays(struct bench *b)
{
	struct renderer_stats stats;

	for (int k = 0; k < 3; k++) {
		struct display_config cfg = {.width = b->width * ss_factors[k],
					     .height = b->height * ss_factors[k]};

		b->display[k] = b->egl ? display_egl_new(&cfg) : display_osmesa_new(&cfg);
		if (!b->display[k])
			return -ENODEV;
		b->display[k]->begin_frame(b->display[k]);
		b->renderer[k] = renderer_new(&b->display[k]->gl, NULL);
		if (!b->renderer[k])
			return -ENOMEM;
	}
	/* EGL headless beside them: plain, and multisampled where it can be. */
	for (int k = 3; k < DISPLAYS; k++) {
		struct display_config cfg = {
		    .width = b->width, .height = b->height, .antialias = msaa_asked[k - 3]};

		b->display[k] = display_egl_new(&cfg);
		if (k > 3 && b->display[k] && !b->display[k]->samples) {
			display_free(b->display[k]);
			b->display[k] = NULL;
		}
		if (!b->display[k])
			continue;
		b->display[k]->begin_frame(b->display[k]);
		b->renderer[k] = renderer_new(&b->display[k]->gl, NULL);
		if (!b->renderer[k])
			return -ENOMEM;
	}
	b->display[0]->begin_frame(b->display[0]);
	renderer_get_stats(b->renderer[0], &stats);
	b->highp_default = stats.highp;
	/* The renderer's own defaults, as the kiosk draws. */
	b->filter_default = stats.matcap_filter;
	b->format_default = stats.format;
	return 0;
}

int main(int argc, char **argv)
{
	static struct bench b = {.last_display = -1};
	int ret;

	log_set_level(LOG_WARN);
	if (parse_args(&b, argc, argv)) {
		fprintf(stderr, "usage: bench_quality OUTDIR SCRATCH [--frames N] [--size WxH] "
				"[--backend osmesa|egl-headless] [--only TEXT]\n");
		return 2;
	}
	snprintf(b.detail_path, sizeof(b.detail_path), "%s/detail.png", b.scratch);
	ret = maps_write(b.scratch) ? -EIO : open_displays(&b);
	for (int i = 0; i < 5 && !ret; i++)
		ret = bake_matcap(BAKE_GOLD, matcap_sizes[i], &b.matcap[i]);
	read_load(b.load[0], sizeof(b.load[0]));
	for (size_t l = 0; l < LOOKS && !ret; l++) {
		if (b.only && !strstr(looks[l].name, b.only))
			continue;
		if (looks[l].model == ENGINE && access(ENGINE_GLB, R_OK)) {
			fprintf(stderr, "  %s: left out, no %s (assimp-testmodels)\n",
				looks[l].name, ENGINE_GLB);
			continue;
		}
		plan(&b, (int)l);
		ret = run_look(&b, (int)l);
		mark_front(b.settings[l], b.count[l]);
	}
	read_load(b.load[1], sizeof(b.load[1]));
	if (!ret)
		ret = bench_write_report(&b);
	for (int k = 0; k < DISPLAYS; k++) {
		if (b.display[k])
			b.display[k]->begin_frame(b.display[k]);
		renderer_free(b.renderer[k]);
		display_free(b.display[k]);
	}
	for (int i = 0; i < 5; i++)
		image_release(&b.matcap[i]);
	if (ret)
		fprintf(stderr, "bench_quality: failed (%s)\n", strerror(-ret));
	return ret ? 1 : 0;
}
