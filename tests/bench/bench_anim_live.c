/* What live playback costs a frame (issue 26), printed and never asserted:
 * a model loaded as the live kiosk loads it, played by its animation
 * player (src/app/kiosk_anim.h) a 30th of a second a frame, each frame
 * posed (samplers, node worlds, skin or morphs, the fit) and its bones or
 * arrays replaced, then drawn and finished (glFinish); beside it the
 * same model as a still (no pose, its compact arrays, its level of
 * detail), frames taken in turn so that a busy machine slows both alike.
 * One row of medians: the path, vertices and triangles played, ms to pose
 * and set the bones or arrays, ms to draw; the still's triangles and ms
 * to draw.
 * The pose is the GPU's (skinning and morph targets in the vertex shader,
 * the bones and weights set a frame) where the model fits its palette
 * and attributes; with `cpu-morphs` the morph targets move the arrays on
 * the CPU (no attribute left for them), the skin on the GPU; with `cpu`
 * all is posed on the CPU.
 *   bench_anim_live osmesa|egl-headless WxH MODEL [FRAMES [gpu|cpu-morphs|cpu]] */
#include "app/kiosk_anim.h"
#include "config/settings.h"
#include "content/content.h"
#include "display/display.h"
#include "util/log.h"

#include "bench_clock.h"
#include "bench_display.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

struct shown {
	struct content_config c;
	struct content s;
	struct renderer *r;
	struct view v;
};

/* bones: the palette at most (0: the CPU path); cpu_morphs: no attribute
 * left for morph targets (they move on the CPU, the skin on the GPU). */
static int show(struct display *d, const char *model, bool live, uint32_t bones, bool cpu_morphs,
		struct shown *out)
{
	struct options o;

	option_defaults(&o);
	o.content.model = (char *)model;
	o.content.anim_live = live;
	o.content.anim_time = live ? -1 : 0;
	o.content.anim_fps = 0;
	out->c = o.content;
	out->r = renderer_new(&d->gl, NULL);
	if (out->r) {
		renderer_set_bone_limit(out->r, bones);
		renderer_set_attribute_limit(out->r, cpu_morphs ? 1 : 0);
	}
	if (!out->r || content_load(&out->s, &out->c, true) ||
	    content_prepare(&out->s, &out->c, d->width, d->height) ||
	    content_upload(&out->s, out->r) || renderer_set_mode(out->r, out->c.mode, out->c.ortho))
		return -1;
	out->v = content_view(&out->c);
	out->v.zoom = (float)out->s.zoom;
	return live && !out->s.play ? -1 : 0;
}

static double draw(struct display *d, struct shown *s)
{
	double t = bench_now_ms();

	renderer_draw(s->r, &s->v, d->width, d->height);
	d->gl.Finish();
	return bench_now_ms() - t;
}

int main(int argc, char **argv)
{
	struct display_config cfg = {0};
	struct display *d = NULL;
	struct shown live, still;
	int n = argc > 4 ? atoi(argv[4]) : 100;
	double *pose, *drawn, *plain;
	struct kiosk_anim *a = kiosk_anim_new();
	struct kiosk_anim_input in = {.running = true};
	uint64_t next, now = 1000000000ull;
	const char *path = argc > 5 ? argv[5] : "gpu";

	if (argc < 4 || sscanf(argv[2], "%dx%d", &cfg.width, &cfg.height) != 2 || n < 2) {
		fprintf(stderr, "usage: bench_anim_live osmesa|egl-headless WxH MODEL [FRAMES "
				"[gpu|cpu-morphs|cpu]]\n");
		return 2;
	}
	log_set_level(LOG_WARN);
	/* An empty cache of its own: the still is parsed too, and nothing is
	 * written where a user's cache is (/nonexistent can exist). */
	char cache[] = "/tmp/mk-bench-anim-XXXXXX", cmd[64];
	if (!mkdtemp(cache))
		return 1;
	setenv("XDG_CACHE_HOME", cache, 1);
	d = bench_display_open(argv[1], &cfg);
	if (!d || d->begin_frame(d) || !a ||
	    show(d, argv[3], true, !strcmp(path, "cpu") ? 0 : UINT32_MAX,
		 !strcmp(path, "cpu-morphs"), &live) ||
	    show(d, argv[3], false, 0, false, &still))
		return 1;
	in.config = &live.c;
	pose = calloc((size_t)n, sizeof(*pose));
	drawn = calloc((size_t)n, sizeof(*drawn));
	plain = calloc((size_t)n, sizeof(*plain));
	if (!pose || !drawn || !plain)
		return 1;
	kiosk_anim_step(a, &live.s, live.r, &in, now, &next);
	draw(d, &live); /* the first draws compile and upload */
	draw(d, &still);
	for (int i = 0; i < n; i++) {
		double t = bench_now_ms();

		now += 33333333ull;
		kiosk_anim_step(a, &live.s, live.r, &in, now, &next);
		pose[i] = bench_now_ms() - t;
		drawn[i] = draw(d, &live);
		plain[i] = draw(d, &still);
	}
	printf("| %s | %s | %s %dx%d | %u | %u | %.3f | %.3f | %u | %.3f |\n",
	       strrchr(argv[3], '/') + 1,
	       live.s.play_ops == &content_deform_cpu ? "CPU"
	       : live.s.play->morphs		      ? "GPU, morphs on the CPU"
	       : live.s.play->morph_targets	      ? "GPU, morphs too"
						      : "GPU",
	       argv[1], cfg.width, cfg.height, live.s.mesh.vertex_count,
	       live.s.mesh.index_count / 3, bench_median(pose, n), bench_median(drawn, n),
	       still.s.mesh.index_count / 3, bench_median(plain, n));
	snprintf(cmd, sizeof(cmd), "rm -rf %s", cache);
	return system(cmd) != 0;
}
