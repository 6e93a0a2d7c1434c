/* The live kiosk's animation player (src/app/kiosk_anim.h), drawn through
 * OSMesa: it asks for frames at animation_fps and none while paused or
 * held, STEP keys at their own rate, a next-animation, a reload and a
 * guided stop's clip crossfade, "all" is a step of the cycle, and a model
 * without animation, or with none of the clip named, gets no player work
 * and exactly the arrays it had. Its frames against the stills:
 * test_anim_frames.c. */
#include "util/clock.h"
#include "gltf_write.h"

#include <math.h>
#include <string.h>
#include <unistd.h>

#include "anim_fixture.h"

/* Frames at animation_fps, none while held; the clock holds with it. */
static void frames_at_the_rate(void **state)
{
	(void)state;
	struct content_config c = config("tests/corpus/khronos/BoxAnimated.gltf", -1);
	struct content s;
	struct renderer *r;
	struct kiosk_anim *a = kiosk_anim_new();
	struct kiosk_anim_input in = {.running = true, .config = &c};
	uint64_t next, now = T0;
	int frames = 0;
	double held;

	c.anim_fps = 20;
	r = shown(&s, &c);
	assert_true(kiosk_anim_step(a, &s, r, &in, now, &next));
	assert_int_equal(next, now + 50000000ull);
	/* A loop woken every millisecond for a second draws 20 frames. */
	for (int i = 1; i <= 1000; i++)
		frames += kiosk_anim_step(a, &s, r, &in, now + i * 1000000ull, &next);
	assert_int_equal(frames, 20);
	now += 1000000000ull;
	/* Held (idle past animation_pause_after, asleep, play-pause): no
	 * frame, no deadline, and the clock stands still. */
	held = kiosk_anim_time(a);
	in.running = false;
	assert_false(kiosk_anim_step(a, &s, r, &in, now + 500000000ull, &next));
	assert_int_equal(next, CLOCK_NEVER);
	in.running = true;
	in.paused = true;
	assert_false(kiosk_anim_step(a, &s, r, &in, now + 900000000ull, &next));
	assert_int_equal(next, CLOCK_NEVER);
	in.paused = false;
	assert_true(kiosk_anim_step(a, &s, r, &in, now + 1000000000ull, &next));
	assert_true(fabs(kiosk_anim_time(a) - held) < 1e-6);
	/* A model uploaded while held is posed once (its first pose), and
	 * asks for nothing more. */
	in.running = false;
	assert_int_equal(content_upload_model(&s, r), 0);
	assert_true(kiosk_anim_step(a, &s, r, &in, now + 1100000000ull, &next));
	assert_int_equal(next, CLOCK_NEVER);
	assert_false(kiosk_anim_step(a, &s, r, &in, now + 1200000000ull, &next));
	kiosk_anim_free(a);
	renderer_free(r);
	content_release(&s);
}

/* A clip of STEP keys alone (a sphere's node turned at 0, 1 and 2 s)
 * draws at its own rate: a frame when a key comes, none between, however
 * high animation_fps is. */
static void step_keys_draw_at_their_rate(void **state)
{
	(void)state;
	char dir[] = "/tmp/mk-step-XXXXXX", path[64];
	struct gltf_write_opts o = {.index_bytes = 4,
				    .with_normals = 1,
				    .bad_index = -1,
				    .with_anim = 1,
				    .anim_node = 0,
				    .anim_step = 1};
	struct mesh sphere;
	struct content_config c;
	struct content s;
	struct renderer *r;
	struct kiosk_anim *a = kiosk_anim_new();
	struct kiosk_anim_input in = {.running = true};
	uint64_t next;
	int frames = 0;

	assert_non_null(mkdtemp(dir));
	snprintf(path, sizeof(path), "%s/step.glb", dir);
	assert_int_equal(mesh_uv_sphere(&sphere, 12, 8), 0);
	assert_int_equal(gltf_write(path, &sphere, &o), 0);
	c = config(path, -1);
	c.anim_fps = 60;
	in.config = &c;
	r = shown(&s, &c);
	assert_non_null(s.play);
	assert_true(kiosk_anim_step(a, &s, r, &in, T0, &next));
	assert_int_equal(next, T0 + 1001000000ull); /* the key at 1 s, not 1/60 s */
	for (int i = 1; i <= 1999; i++)
		frames += kiosk_anim_step(a, &s, r, &in, T0 + i * 1000000ull, &next);
	assert_int_equal(frames, 1);
	kiosk_anim_free(a);
	renderer_free(r);
	content_release(&s);
	mesh_release(&sphere);
	unlink(path);
	rmdir(dir);
}

/* next-animation: the pose shown blends into the next clip's (here the
 * same clip again from its start) over KIOSK_ANIM_FADE_NS. */
static void next_animation_crossfades(void **state)
{
	(void)state;
	struct content_config c = config("tests/corpus/khronos/SimpleMorph.gltf", -1);
	struct content s;
	struct renderer *r = shown(&s, &c);
	struct kiosk_anim *a = kiosk_anim_new();
	struct kiosk_anim_input in = {.running = true, .config = &c};
	uint64_t next;
	size_t n = (size_t)s.mesh.vertex_count * 3;
	float *before = malloc(n * sizeof(float)), *start = malloc(n * sizeof(float));

	assert_true(kiosk_anim_step(a, &s, r, &in, T0, &next));
	memcpy(start, s.mesh.positions, n * sizeof(float)); /* the clip at 0 s */
	assert_true(kiosk_anim_step(a, &s, r, &in, T0 + 1000000000ull, &next));
	memcpy(before, s.mesh.positions, n * sizeof(float)); /* at 1 s */
	in.clip_step = 1;
	/* Half-way through the fade: between the pose left and the new
	 * clip's start, not at either. */
	assert_true(kiosk_anim_step(a, &s, r, &in, T0 + 1000000000ull, &next));
	assert_true(kiosk_anim_step(a, &s, r, &in, T0 + 1125000000ull, &next));
	double off_before = 0, off_start = 0;

	for (size_t i = 0; i < n; i++) {
		off_before = fmax(off_before, fabs(s.mesh.positions[i] - before[i]));
		off_start = fmax(off_start, fabs(s.mesh.positions[i] - start[i]));
	}
	assert_true(off_before > 1e-3 && off_start > 1e-3);
	/* The same model uploaded again (a swap put back): its arrays are new
	 * on the GPU, and the player poses them at once. */
	assert_false(kiosk_anim_step(a, &s, r, &in, T0 + 1126000000ull, &next));
	assert_int_equal(content_upload_model(&s, r), 0);
	assert_true(kiosk_anim_step(a, &s, r, &in, T0 + 1127000000ull, &next));
	free(before);
	free(start);
	kiosk_anim_free(a);
	renderer_free(r);
	content_release(&s);
}

/* BoxAnimated's vertices posed on the CPU as the player shows them. */
static float *posed(const struct content *s)
{
	size_t n = (size_t)s->mesh.vertex_count * 3 * sizeof(float);
	float *p = malloc(n);

	assert_non_null(p);
	memcpy(p, s->mesh.positions, n);
	return p;
}

static double farthest(const float *a, const float *b, size_t n)
{
	double most = 0;

	for (size_t i = 0; i < n; i++)
		most = fmax(most, fabs(a[i] - b[i]));
	return most;
}

/* A reload of the model on screen (its file or its settings changed)
 * goes on: the same clip keeps its clock, a clip played otherwise starts
 * from the pose shown and crossfades. */
static void reload_goes_on(void **state)
{
	(void)state;
	struct content_config c = config(KHRONOS "BoxAnimated.gltf", -1);
	struct content s[3];
	struct kiosk_anim *a = kiosk_anim_new();
	struct kiosk_anim_input in = {.running = true, .config = &c};
	struct renderer *r;
	uint64_t next, at = T0 + 1000000000ull;
	float *before, *after;
	size_t n;

	c.animation = "1";
	r = shown_with(&s[0], &c, 0); /* posed on the CPU: its arrays show it */
	assert_true(kiosk_anim_step(a, &s[0], r, &in, T0, &next));
	assert_true(kiosk_anim_step(a, &s[0], r, &in, at, &next));
	assert_true(fabs(kiosk_anim_time(a) - 1.0) < 1e-6);
	/* Loaded again, the same clip: its clock goes on (not from 0). */
	assert_int_equal(content_load(&s[1], &c, true), 0);
	assert_int_equal(content_prepare(&s[1], &c, SIZE, SIZE), 0);
	assert_int_equal(content_upload(&s[1], r), 0);
	content_release(&s[0]);
	assert_true(kiosk_anim_step(a, &s[1], r, &in, at + 500000000ull, &next));
	assert_true(fabs(kiosk_anim_time(a) - 1.5) < 1e-6);
	before = posed(&s[1]);
	n = (size_t)s[1].mesh.vertex_count * 3;
	/* Played otherwise (here twice as fast; another clip alike, but
	 * its own fit would move the arrays): the clip starts again, and the
	 * first frame still shows the pose left, fading from there. */
	c.anim_speed = 2;
	assert_int_equal(content_load(&s[2], &c, true), 0);
	assert_int_equal(content_prepare(&s[2], &c, SIZE, SIZE), 0);
	assert_int_equal(content_upload(&s[2], r), 0);
	content_release(&s[1]);
	assert_true(kiosk_anim_step(a, &s[2], r, &in, at + 500000000ull, &next));
	assert_true(kiosk_anim_time(a) < 1e-6);
	after = posed(&s[2]);
	assert_true(farthest(before, after, n) < 1e-5);
	free(after);
	assert_true(kiosk_anim_step(a, &s[2], r, &in, at + 625000000ull, &next));
	after = posed(&s[2]);
	assert_true(farthest(before, after, n) > 1e-3); /* fading, not held */
	free(after);
	free(before);
	kiosk_anim_free(a);
	renderer_free(r);
	content_release(&s[2]);
}

/* "all": next-animation steps clip 0, clip 1, then all of them again. */
static void all_is_a_step_of_the_cycle(void **state)
{
	(void)state;
	struct content_config c = config(KHRONOS "BoxAnimated.gltf", -1);
	struct content s;
	struct kiosk_anim *a = kiosk_anim_new();
	struct kiosk_anim_input in = {.running = true, .config = &c};
	struct renderer *r;
	uint64_t next;
	float *all, *again;

	c.animation = "all";
	r = shown_with(&s, &c, 0);
	assert_true(kiosk_anim_step(a, &s, r, &in, T0, &next));
	assert_true(kiosk_anim_step(a, &s, r, &in, T0 + KIOSK_ANIM_FADE_NS, &next));
	all = posed(&s); /* both clips at a quarter second */
	for (int step = 1; step <= 3; step++) {
		in.clip_step = step; /* each press long after the last fade */
		assert_true(kiosk_anim_step(a, &s, r, &in, T0 + step * 10000000000ull, &next));
		assert_true(kiosk_anim_step(
		    a, &s, r, &in, T0 + step * 10000000000ull + KIOSK_ANIM_FADE_NS, &next));
	}
	again = posed(&s); /* all again, a quarter second in */
	assert_true(farthest(all, again, (size_t)s.mesh.vertex_count * 3) < 1e-4);
	free(all);
	free(again);
	kiosk_anim_free(a);
	renderer_free(r);
	content_release(&s);
}

/* A guided stop's animation=: reached, its clip plays from the start,
 * faded from the pose shown; a clip the model lacks changes nothing; a
 * model set up at that stop starts with the stop's clip. */
static void stops_play_their_clip(void **state)
{
	(void)state;
	struct content_config c = config(KHRONOS "BoxAnimated.gltf", -1);
	struct content s;
	struct kiosk_anim *a = kiosk_anim_new(), *b = kiosk_anim_new();
	struct kiosk_anim_input in = {.running = true, .config = &c};
	struct renderer *r;
	uint64_t next, at = T0 + 1000000000ull;
	float *before, *after;
	size_t n;

	c.animation = "0";
	r = shown_with(&s, &c, 0);
	n = (size_t)s.mesh.vertex_count * 3;
	assert_true(kiosk_anim_step(a, &s, r, &in, T0, &next));
	assert_true(kiosk_anim_step(a, &s, r, &in, at, &next));
	before = posed(&s);
	in.stop_clip = "1";
	assert_true(kiosk_anim_step(a, &s, r, &in, at, &next));
	assert_true(kiosk_anim_time(a) < 1e-6); /* clip 1 from its start */
	after = posed(&s);
	assert_true(farthest(before, after, n) < 1e-5); /* faded from the pose shown */
	free(after);
	/* A clip the model lacks: the one playing goes on. */
	in.stop_clip = "no such clip";
	assert_true(kiosk_anim_step(a, &s, r, &in, at + 500000000ull, &next));
	assert_true(fabs(kiosk_anim_time(a) - 0.5) < 1e-6);
	/* Set up at a stop with a clip: that clip, as if the setting named
	 * it (not the setting's, whose pose differs then). */
	in.stop_clip = "1";
	assert_true(kiosk_anim_step(b, &s, r, &in, at, &next));
	assert_true(kiosk_anim_step(b, &s, r, &in, at + 700000000ull, &next));
	free(before);
	before = posed(&s);
	in.stop_clip = NULL;
	for (int k = 0; k < 2; k++) {
		c.animation = k ? "0" : "1";
		kiosk_anim_free(b);
		b = kiosk_anim_new();
		assert_int_equal(content_upload_model(&s, r), 0); /* set up again */
		assert_true(kiosk_anim_step(b, &s, r, &in, at, &next));
		assert_true(kiosk_anim_step(b, &s, r, &in, at + 700000000ull, &next));
		after = posed(&s);
		if (k)
			assert_true(farthest(before, after, n) > 1e-3);
		else
			assert_true(farthest(before, after, n) < 1e-6);
		free(after);
	}
	free(before);
	kiosk_anim_free(a);
	kiosk_anim_free(b);
	renderer_free(r);
	content_release(&s);
}

/* No animation: no playback data, no frame asked for, and the same
 * arrays (the compact format) as ever. */
static void still_models_cost_nothing(void **state)
{
	(void)state;
	struct content_config c = config("tests/corpus/khronos/MultipleScenes.gltf", -1);
	struct content s;
	struct renderer *r = renderer_new(&d->gl, NULL);
	struct kiosk_anim *a = kiosk_anim_new();
	struct kiosk_anim_input in = {.running = true, .config = &c};
	struct renderer_stats st;

	assert_int_equal(content_load(&s, &c, true), 0);
	assert_int_equal(content_prepare(&s, &c, SIZE, SIZE), 0);
	assert_int_equal(content_upload(&s, r), 0);
	uint64_t next;

	assert_null(s.play);
	assert_false(kiosk_anim_step(a, &s, r, &in, T0, &next));
	assert_int_equal(next, CLOCK_NEVER);
	renderer_get_stats(r, &st);
	assert_int_equal(st.format, VERTEX_COMPACT);
	kiosk_anim_free(a);
	renderer_free(r);
	content_release(&s);
}

/* A clip the file lacks is no error in the live kiosk (a folder's other
 * models may have it): the model loads, still, in its rest pose. */
static void a_clip_it_lacks_shows_still(void **state)
{
	(void)state;
	struct content_config c = config("tests/corpus/khronos/RiggedSimple.gltf", -1);
	struct content s;

	c.animation = "walk";
	assert_int_equal(content_load(&s, &c, true), 0);
	assert_null(s.play);
	content_release(&s);
	c.anim_live = false; /* a still (--time) names the setting: an error */
	c.anim_time = 1;
	assert_int_not_equal(content_load(&s, &c, true), 0);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(frames_at_the_rate),
	    cmocka_unit_test(step_keys_draw_at_their_rate),
	    cmocka_unit_test(next_animation_crossfades),
	    cmocka_unit_test(reload_goes_on),
	    cmocka_unit_test(all_is_a_step_of_the_cycle),
	    cmocka_unit_test(stops_play_their_clip),
	    cmocka_unit_test(still_models_cost_nothing),
	    cmocka_unit_test(a_clip_it_lacks_shows_still),
	};

	return anim_tests_run("kiosk_anim", tests, sizeof(tests) / sizeof(tests[0]));
}
