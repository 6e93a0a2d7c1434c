#include "app/kiosk_anim.h"
#include "app/kiosk_state.h"
#include "state/view.h"
#include "util/clock.h"
#include "util/log.h"

#include <stdlib.h>
#include <string.h>

/* 2020-01-01 on the shared clock: a loop's phase counts from there, well
 * within anim_clock_seek's exact range. */
#define SHARED_EPOCH_NS (1577836800ull * 1000000000ull)

struct kiosk_anim {
	const struct anim_play *play; /* the content's it was set up for */
	unsigned serial;	      /* the renderer's mesh it was set up for */
	struct anim_pose *pose, *from, *mix;
	/* A clock per clip: one plays, or all of them together ("all"), each
	 * looping on its own length as the --time still samples them. */
	struct anim_clock *clocks;
	size_t clip_count;
	/* The setting's clip, and the one playing; clip_count: all of them;
	 * -1: none. */
	int first_clip, clip;
	int clip_step;			 /* the app state's count of next-animation seen */
	uint64_t last_ns;		 /* the clock has run to here */
	uint64_t due_ns;		 /* the next frame */
	uint64_t fade_ns;		 /* a crossfade started then; 0: none */
	bool held;			 /* the clock stood still: it goes on from the next step */
	uint64_t shared_ns;		 /* the shared clock now ([kiosk] clock); 0: its own */
	char stop_clip[FRAME_STOP_CLIP]; /* the stop's clip last seen; "": none */
	bool stop_warned;		 /* a stop named a clip this model lacks: said */
	/* The file set up for and its shape (its playback may be freed by
	 * now): a reload of it keeps its clocks or fades from its pose. */
	char *model;
	size_t node_count, weight_total;
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
	free(a->clocks);
	free(a->model);
	a->clocks = NULL;
	a->model = NULL;
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

/* The clips playing: [*first, *end). */
static void playing(const struct kiosk_anim *a, size_t *first, size_t *end)
{
	bool all = a->clip == (int)a->clip_count;

	*first = all ? 0 : (size_t)a->clip;
	*end = all ? a->clip_count : (size_t)a->clip + 1;
}

static void start_clip(struct kiosk_anim *a, const struct content_config *cfg, int clip,
		       uint64_t now)
{
	const struct mesh_anim *m = a->play->anim;
	size_t k, end;

	a->clip = clip;
	for (playing(a, &k, &end); k < end; k++) {
		anim_clock_init(&a->clocks[k], m->clips[k].duration, (enum anim_loop)cfg->anim_loop,
				cfg->anim_speed > 0 ? cfg->anim_speed : 1.0);
		/* On a shared clock a loop is where every kiosk's is: at its
		 * time since 2020 (a once clip plays from its start). */
		if (a->shared_ns > SHARED_EPOCH_NS && cfg->anim_loop != ANIM_ONCE)
			anim_clock_seek(&a->clocks[k],
					(double)(a->shared_ns - SHARED_EPOCH_NS) / 1e9);
	}
	a->last_ns = a->due_ns = now;
}

static void log_clip(const struct kiosk_anim *a, const char *path)
{
	const struct mesh_anim *m = a->play->anim;

	if (a->clip == (int)m->clip_count) {
		log_info("%s: plays all %zu animations together live", path, m->clip_count);
		return;
	}
	log_info("%s: plays animation %d of %zu (%s, %.2f s) live", path, a->clip, m->clip_count,
		 m->clips[a->clip].name ? m->clips[a->clip].name : "unnamed",
		 m->clips[a->clip].duration);
}

/* The same file again (a reload: its settings or the file changed) with
 * the same nodes and morph weights: the pose shown can go on into the new
 * content's, without a jump. */
static bool same_model(const struct kiosk_anim *a, const struct content *c)
{
	const struct mesh_anim *now = c->play->anim;

	return a->pose && a->model && c->model_path && !strcmp(a->model, c->model_path) &&
	       a->node_count == now->node_count && a->weight_total == now->weight_total &&
	       a->clip_count == now->clip_count;
}

/* What a reload of the same model keeps: the clocks where the clip is
 * the same (and its loop and speed), else the pose shown, faded from. */
static void carry_over(struct kiosk_anim *a, struct anim_pose *shown, struct anim_clock *clocks,
		       int clip, uint64_t last_ns, uint64_t now)
{
	size_t k, end;
	bool same = clip == a->clip;

	for (playing(a, &k, &end); same && k < end; k++)
		same = clocks[k].duration_ns == a->clocks[k].duration_ns &&
		       clocks[k].loop == a->clocks[k].loop && clocks[k].speed == a->clocks[k].speed;
	if (same) { /* and the time since it last ran */
		memcpy(a->clocks, clocks, a->clip_count * sizeof(*clocks));
		a->last_ns = last_ns;
		return;
	}
	copy_pose(a->play->anim, a->from, shown);
	a->fade_ns = now ? now : 1;
}

/* The clip words name ([scene] animation's: auto, a name, an index; all:
 * clip_count), -1 for off or none, -2 for a name the model lacks. */
static int find_clip(const struct kiosk_anim *a, const char *words)
{
	if (!strcmp(words, "all"))
		return a->clip_count ? (int)a->clip_count : -1;
	return anim_clip_find(a->play->anim, words);
}

/* The clip [scene] animation names for this content ("all": every clip,
 * each on its own clock; "off": none). */
static void set_up(struct kiosk_anim *a, const struct content *c, const struct renderer *r,
		   const struct kiosk_anim_input *in, uint64_t now)
{
	const char *want = in->config->animation ? in->config->animation : "auto";
	struct anim_pose *shown = NULL;
	struct anim_clock *clocks = NULL;
	int clip, was_clip = a->clip;
	uint64_t was_ns = a->last_ns;
	bool again = c->play && same_model(a, c);

	if (again) { /* kept from the old set-up until the new one is made */
		shown = a->fade_ns ? a->mix : a->pose;
		if (a->fade_ns)
			a->mix = NULL;
		else
			a->pose = NULL;
		clocks = a->clocks;
		a->clocks = NULL;
	}
	drop_poses(a);
	a->play = c->play;
	a->serial = renderer_mesh_serial(r);
	a->clip = -1;
	a->fade_ns = 0;
	a->clip_step = in->clip_step;
	a->stop_warned = false;
	if (!a->play || !c->play_ops) /* not uploaded to play: shown still */
		goto out;
	a->clip_count = a->play->anim->clip_count;
	a->node_count = a->play->anim->node_count;
	a->weight_total = a->play->anim->weight_total;
	clip = find_clip(a, want);
	if (in->stop_clip && find_clip(a, in->stop_clip) >= 0) /* shown at a stop that plays one */
		clip = find_clip(a, in->stop_clip);
	snprintf(a->stop_clip, sizeof(a->stop_clip), "%s", in->stop_clip ? in->stop_clip : "");
	a->pose = anim_pose_new(a->play->anim);
	a->from = anim_pose_new(a->play->anim);
	a->mix = anim_pose_new(a->play->anim);
	a->clocks = calloc(a->clip_count + 1, sizeof(*a->clocks));
	a->model = c->model_path ? strdup(c->model_path) : NULL;
	if (clip < 0 || !a->pose || !a->from || !a->mix || !a->clocks ||
	    (c->model_path && !a->model)) {
		drop_poses(a);
		goto out;
	}
	a->first_clip = clip;
	start_clip(a, in->config, clip, now);
	if (again && was_clip >= 0)
		carry_over(a, shown, clocks, was_clip, was_ns, now);
	log_clip(a, c->model_path ? c->model_path : "the model");
out:
	anim_pose_free(shown);
	free(clocks);
}

/* The pose shown now fades into clip's. */
static void fade_to(struct kiosk_anim *a, const struct content_config *cfg, int clip, uint64_t now)
{
	copy_pose(a->play->anim, a->from, a->fade_ns ? a->mix : a->pose);
	a->fade_ns = now ? now : 1;
	start_clip(a, cfg, clip, now);
}

/* A guided stop reached that names a clip: it plays, faded into, unless
 * it is the one playing; a name the model lacks is said once a model
 * (attract mode comes back to the stop every round). */
static void stop_clip(struct kiosk_anim *a, const struct kiosk_anim_input *in, uint64_t now)
{
	int clip;

	snprintf(a->stop_clip, sizeof(a->stop_clip), "%s", in->stop_clip ? in->stop_clip : "");
	if (!in->stop_clip)
		return;
	clip = find_clip(a, in->stop_clip);
	if (clip == -2 && !a->stop_warned)
		log_warn("[frame] stops: animation=%s: %s has no such animation; the one playing "
			 "goes on",
			 in->stop_clip, a->model ? a->model : "the model");
	a->stop_warned |= clip == -2;
	if (clip >= 0 && clip != a->clip)
		fade_to(a, in->config, clip, now);
}

/* next-animation: the pose shown now fades into the next clip's ("all"
 * is one more step of the cycle when the setting asks for it). */
static void next_clip(struct kiosk_anim *a, const struct kiosk_anim_input *in, uint64_t now)
{
	size_t n = a->clip_count + (a->first_clip == (int)a->clip_count);
	int clip = (int)(((size_t)a->first_clip + (size_t)(unsigned)in->clip_step) % n);

	a->clip_step = in->clip_step;
	fade_to(a, in->config, clip, now);
}

static void pose_now(struct kiosk_anim *a, struct content *c, struct renderer *r, uint64_t now)
{
	const struct mesh_anim *m = a->play->anim;
	const struct anim_pose *shown = a->pose;
	size_t k, end;

	anim_pose_rest(m, a->pose);
	for (playing(a, &k, &end); k < end; k++)
		anim_pose_apply(m, &m->clips[k], anim_clock_time(&a->clocks[k]), a->pose);
	if (a->fade_ns && now - a->fade_ns < KIOSK_ANIM_FADE_NS) {
		copy_pose(m, a->mix, a->from);
		anim_pose_blend(m, a->mix, a->pose,
				(double)(now - a->fade_ns) / (double)KIOSK_ANIM_FADE_NS);
		shown = a->mix;
	} else {
		a->fade_ns = 0;
	}
	c->play_ops->pose(c, r, shown);
	content_hotspots_follow(c, r);
}

/* Until the next frame: the cap's period, or longer while every clip
 * playing holds its pose (STEP keys alone: the animation's own rate); 1 ms
 * past the first key to come, so that its pose is the new one. */
static uint64_t frame_wait(const struct kiosk_anim *a, double fps)
{
	uint64_t period = fps > 0 ? (uint64_t)(1e9 / fps) : 0;
	double wait = 1e18;
	size_t i, end;

	if (a->fade_ns)
		return period;
	for (playing(a, &i, &end); i < end; i++) {
		const struct anim_clock *k = &a->clocks[i];
		bool back = k->loop == ANIM_PINGPONG && k->phase_ns > k->duration_ns;
		double hold = anim_clip_hold(&a->play->anim->clips[i], anim_clock_time(k), back);

		if (hold <= 0)
			return period;
		if (hold / k->speed * 1e9 + 1e6 < wait)
			wait = hold / k->speed * 1e9 + 1e6;
	}
	return wait < (double)period ? period : (uint64_t)wait;
}

static void clocks_advance(struct kiosk_anim *a, uint64_t wall_ns)
{
	size_t k, end;

	for (playing(a, &k, &end); k < end; k++)
		anim_clock_advance(&a->clocks[k], wall_ns);
}

/* false once no clip playing moves (each `once` ended). */
static bool clocks_moving(const struct kiosk_anim *a)
{
	size_t k, end;

	for (playing(a, &k, &end); k < end; k++)
		if (anim_clock_moving(&a->clocks[k]))
			return true;
	return false;
}

bool kiosk_anim_step(struct kiosk_anim *a, struct content *c, struct renderer *r,
		     const struct kiosk_anim_input *in, uint64_t now, uint64_t *next)
{
	/* Another mesh uploaded (another model, or one put back): set up
	 * again, whatever its address. */
	bool fresh = a->play != c->play || a->serial != renderer_mesh_serial(r);
	double fps = in->config->anim_fps;

	*next = CLOCK_NEVER;
	a->shared_ns = in->shared_ns;
	if (fresh)
		set_up(a, c, r, in, now);
	if (a->clip < 0)
		return false;
	if (in->clip_step != a->clip_step)
		next_clip(a, in, now);
	if (strcmp(in->stop_clip ? in->stop_clip : "", a->stop_clip))
		stop_clip(a, in, now);
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
	clocks_advance(a, now - a->last_ns);
	a->last_ns = now;
	pose_now(a, c, r, now);
	a->due_ns = now + frame_wait(a, fps);
	/* once, ended: nothing moves until the clip changes. */
	if (clocks_moving(a) || a->fade_ns)
		*next = a->due_ns;
	return true;
}

double kiosk_anim_time(const struct kiosk_anim *a)
{
	size_t k, end;

	if (a->clip < 0)
		return -1.0;
	playing(a, &k, &end);
	return anim_clock_time(&a->clocks[k]);
}

/* The loop's side (kiosk_state.h): whether the animation runs, and a
 * frame asked for when the pose changed. */
uint64_t kiosk_play_animation(struct kiosk *k, uint64_t now, bool awake)
{
	const struct app_state *st = app_state(k->app);
	const struct content_config *cfg = content_settings(k->content, &k->applied.content);
	uint64_t started = app_clock(k->app, k->started_ns), t = app_clock(k->app, now);
	uint64_t input = st->last_input_ns > started ? st->last_input_ns : started;
	double idle = (double)(t > input ? t - input : 0) / 1e9;
	struct kiosk_anim_input in = {
	    .running = awake && (cfg->anim_pause_after <= 0 || idle < cfg->anim_pause_after),
	    .paused = st->anim_paused,
	    .clip_step = st->anim_step,
	    .stop_clip = st->stop_animation,
	    .config = cfg,
	    .shared_ns = k->applied.app.shared_clock ? t : 0};
	uint64_t next;

	/* A flip pending: its end wakes the loop, which poses then. */
	if (!k->anim || k->display->waiting)
		return CLOCK_NEVER;
	if (kiosk_anim_step(k->anim, k->content, k->renderer, &in, now, &next))
		kiosk_tell_app(k, APP_DISPLAY_BACK);
	return next;
}
