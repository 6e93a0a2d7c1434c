#include "app/kiosk_anim.h"
#include "app/kiosk_state.h"
#include "util/clock.h"
#include "util/log.h"

#include <stdlib.h>
#include <string.h>

struct kiosk_anim {
	const struct anim_play *play; /* the content's it was set up for */
	unsigned serial;	      /* the renderer's mesh it was set up for */
	struct anim_pose *pose, *from, *mix;
	struct anim_clock clock;
	int first_clip, clip; /* the setting's, and the one playing; -1: none */
	int clip_step;	      /* the app state's count of next-animation seen */
	uint64_t last_ns;     /* the clock has run to here */
	uint64_t due_ns;      /* the next frame */
	uint64_t fade_ns;     /* a crossfade started then; 0: none */
	bool held;	      /* the clock stood still: it goes on from the next step */
	float *rows;	      /* the bone palette's rows (skinned on the GPU) */
};

struct kiosk_anim *kiosk_anim_new(void)
{
	struct kiosk_anim *a = calloc(1, sizeof(*a));

	if (a)
		a->clip = -1;
	return a;
}

static void drop_poses(struct kiosk_anim *a)
{
	free(a->rows);
	a->rows = NULL;
	anim_pose_free(a->pose);
	anim_pose_free(a->from);
	anim_pose_free(a->mix);
	a->pose = a->from = a->mix = NULL;
}

void kiosk_anim_free(struct kiosk_anim *a)
{
	if (!a)
		return;
	drop_poses(a);
	free(a);
}

static void copy_pose(const struct mesh_anim *m, struct anim_pose *to, const struct anim_pose *p)
{
	memcpy(to->local, p->local, m->node_count * sizeof(*p->local));
	memcpy(to->weights, p->weights, m->weight_total * sizeof(*p->weights));
}

static void start_clip(struct kiosk_anim *a, const struct content_config *cfg, int clip,
		       uint64_t now)
{
	const struct mesh_anim *m = a->play->anim;

	a->clip = clip;
	anim_clock_init(&a->clock, m->clips[clip].duration, (enum anim_loop)cfg->anim_loop,
			cfg->anim_speed > 0 ? cfg->anim_speed : 1.0);
	a->last_ns = a->due_ns = now;
}

/* The clip [scene] animation names for this content; "all" plays the
 * first (a clock per clip would be needed), "off" none. */
static void set_up(struct kiosk_anim *a, const struct content *c, const struct renderer *r,
		   const struct kiosk_anim_input *in, uint64_t now)
{
	const char *want = in->config->animation ? in->config->animation : "auto";
	int clip;

	drop_poses(a);
	a->play = c->play;
	a->serial = renderer_mesh_serial(r);
	a->clip = -1;
	a->fade_ns = 0;
	a->clip_step = in->clip_step;
	if (!a->play)
		return;
	clip = anim_clip_find(a->play->anim, want);
	if (!strcmp(want, "all") && a->play->anim->clip_count)
		clip = 0;
	a->pose = anim_pose_new(a->play->anim);
	a->from = anim_pose_new(a->play->anim);
	a->mix = anim_pose_new(a->play->anim);
	a->rows = c->play_gpu ? malloc((size_t)a->play->bones * 12 * sizeof(float)) : NULL;
	if (clip < 0 || !a->pose || !a->from || !a->mix || (c->play_gpu && !a->rows)) {
		drop_poses(a);
		return;
	}
	a->first_clip = clip;
	start_clip(a, in->config, clip, now);
	log_info("%s: plays animation %d of %zu (%s, %.2f s) live", c->model_path, clip,
		 a->play->anim->clip_count,
		 a->play->anim->clips[clip].name ? a->play->anim->clips[clip].name : "unnamed",
		 a->play->anim->clips[clip].duration);
}

/* next-animation: the pose shown now fades into the next clip's. */
static void next_clip(struct kiosk_anim *a, const struct kiosk_anim_input *in, uint64_t now)
{
	size_t n = a->play->anim->clip_count;
	int clip = (int)(((size_t)a->first_clip + (size_t)(unsigned)in->clip_step) % n);

	copy_pose(a->play->anim, a->from, a->fade_ns ? a->mix : a->pose);
	a->fade_ns = now ? now : 1;
	a->clip_step = in->clip_step;
	start_clip(a, in->config, clip, now);
}

static void pose_now(struct kiosk_anim *a, struct content *c, struct renderer *r, uint64_t now)
{
	const struct mesh_anim *m = a->play->anim;
	const struct anim_pose *shown = a->pose;

	anim_pose_rest(m, a->pose);
	anim_pose_apply(m, &m->clips[a->clip], anim_clock_time(&a->clock), a->pose);
	if (a->fade_ns && now - a->fade_ns < KIOSK_ANIM_FADE_NS) {
		copy_pose(m, a->mix, a->from);
		anim_pose_blend(m, a->mix, a->pose,
				(double)(now - a->fade_ns) / (double)KIOSK_ANIM_FADE_NS);
		shown = a->mix;
	} else {
		a->fade_ns = 0;
	}
	if (!c->play_gpu) {
		anim_play_pose(c->play, shown, c->mesh.positions, c->mesh.normals);
		renderer_set_vertices(r, c->mesh.positions, c->mesh.normals);
		return;
	}
	anim_play_bones(c->play, shown, a->rows);
	renderer_set_bones(r, a->rows);
	if (c->play->morph_targets) { /* the vertex shader adds them */
		float w[ANIM_PLAY_MORPH_MAX];

		anim_play_morph_weights(c->play, shown, w);
		renderer_set_morph_weights(r, w);
	}
	/* Morph targets that did not fit the GPU move the parts' own arrays. */
	if (c->play->morphs) {
		const struct anim_play_split *sp = c->play_split;

		anim_play_morph(c->play, shown, c->mesh.positions, c->mesh.normals);
		if (sp) { /* in the split's order */
			anim_play_split_gather(sp, c->mesh.positions, 3, sp->positions);
			anim_play_split_gather(sp, c->mesh.normals, 3, sp->normals);
		}
		renderer_set_vertices(r, sp ? sp->positions : c->mesh.positions,
				      sp ? sp->normals : c->mesh.normals);
	}
}

/* Until the next frame: the cap's period, or longer while the clip's
 * pose holds (STEP keys alone: the animation's own rate); 1 ms past the
 * key, so that its pose is the new one. */
static uint64_t frame_wait(const struct kiosk_anim *a, double fps)
{
	const struct anim_clock *k = &a->clock;
	uint64_t period = fps > 0 ? (uint64_t)(1e9 / fps) : 0;
	bool back = k->loop == ANIM_PINGPONG && k->phase_ns > k->duration_ns;
	double hold = anim_clip_hold(&a->play->anim->clips[a->clip], anim_clock_time(k), back);
	double wait = hold / k->speed * 1e9 + 1e6;

	if (hold <= 0 || a->fade_ns || wait < (double)period)
		return period;
	return wait < 1e18 ? (uint64_t)wait : (uint64_t)1e18;
}

bool kiosk_anim_step(struct kiosk_anim *a, struct content *c, struct renderer *r,
		     const struct kiosk_anim_input *in, uint64_t now, uint64_t *next)
{
	/* Another mesh uploaded (another model, or one put back): set up
	 * again, whatever its address. */
	bool fresh = a->play != c->play || a->serial != renderer_mesh_serial(r);
	double fps = in->config->anim_fps;

	*next = CLOCK_NEVER;
	if (fresh)
		set_up(a, c, r, in, now);
	if (a->clip < 0)
		return false;
	if (in->clip_step != a->clip_step)
		next_clip(a, in, now);
	/* Held: the clock stays where it is, and no frame is due; a new
	 * mesh still gets its first pose (on the GPU path its arrays are the
	 * parts' own, unposed, until the bones are set). */
	if (!in->running || in->paused) {
		a->held = true;
		if (fresh)
			pose_now(a, c, r, now);
		return fresh;
	}
	if (a->held)
		a->last_ns = now;
	a->held = false;
	if (!fresh && now < a->due_ns) {
		*next = a->due_ns;
		return false;
	}
	anim_clock_advance(&a->clock, now - a->last_ns);
	a->last_ns = now;
	pose_now(a, c, r, now);
	a->due_ns = now + frame_wait(a, fps);
	/* once, ended: nothing moves until the clip changes. */
	if (anim_clock_moving(&a->clock) || a->fade_ns)
		*next = a->due_ns;
	return true;
}

double kiosk_anim_time(const struct kiosk_anim *a)
{
	return a->clip >= 0 ? anim_clock_time(&a->clock) : -1.0;
}

/* The loop's side (kiosk_state.h): whether the animation runs, and a
 * frame asked for when the pose changed. */
uint64_t kiosk_play_animation(struct kiosk *k, uint64_t now, bool awake)
{
	const struct app_state *st = app_state(k->app);
	const struct content_config *cfg = content_settings(k->content, &k->applied.content);
	uint64_t input = st->last_input_ns > k->started_ns ? st->last_input_ns : k->started_ns;
	double idle = (double)(now > input ? now - input : 0) / 1e9;
	struct kiosk_anim_input in = {
	    .running = awake && (cfg->anim_pause_after <= 0 || idle < cfg->anim_pause_after),
	    .paused = st->anim_paused,
	    .clip_step = st->anim_step,
	    .config = cfg};
	uint64_t next;

	/* A flip pending: its end wakes the loop, which poses then. */
	if (!k->anim || k->display->waiting)
		return CLOCK_NEVER;
	if (kiosk_anim_step(k->anim, k->content, k->renderer, &in, now, &next))
		kiosk_tell_app(k, APP_DISPLAY_BACK);
	return next;
}
