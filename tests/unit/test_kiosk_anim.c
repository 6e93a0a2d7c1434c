/* The live kiosk's animation player (src/app/kiosk_anim.h), drawn through
 * OSMesa: its frame at a playback time equals the --time still of that
 * time (RiggedSimple's skin, SimpleMorph's and AnimatedMorphCube's
 * weights, BoxAnimated's nodes, a capsule of eight joints a vertex),
 * skinned on the GPU and posed on the CPU, it asks for frames at
 * animation_fps and none while paused or held, a next-animation
 * crossfades, and a model without animation gets no player work and
 * exactly the arrays it had. */
#include "app/kiosk_anim.h"
#include "config/settings.h"
#include "content/content.h"
#include "display/display.h"
#include "util/clock.h"
#include "gltf_joints.h"
#include "gltf_morph.h"
#include "gltf_write.h"

#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <cmocka.h>

#include "offscreen.h"

#define SIZE	96
#define KHRONOS "tests/corpus/khronos/"
#define T0	1000000000ull

static struct display *d;
/* The vertex attributes the next renderer may use (0: the GPU's). */
static uint32_t attribute_limit;

static int open_display(void **state)
{
	(void)state;
	d = offscreen_open(SIZE, SIZE);
	return d ? 0 : -1;
}

static struct content_config config(const char *model, double time)
{
	struct options o;

	option_defaults(&o);
	o.content.model = (char *)model;
	o.content.anim_time = time;
	o.content.anim_live = time < 0;
	o.content.lod_pixels = 0;
	/* The [scene] fit frames the mesh as loaded (the live one at 0 s):
	 * one zoom for both. */
	o.content.zoom = 1.0;
	return o.content;
}

/* The content's frame drawn by r (the kiosk's draw: the view and the fit). */
static void draw(struct renderer *r, const struct content *s, const struct content_config *c,
		 struct image *out)
{
	struct view v = content_view(c);

	v.zoom = (float)s->zoom;
	assert_int_equal(d->begin_frame(d), 0);
	renderer_draw(r, &v, SIZE, SIZE);
	assert_int_equal(display_read_rgba(d, out), 0);
}

/* The live mesh's arrays are float32: the still is drawn from float32
 * arrays too, so that only the poses are compared. bones: the palette at
 * most (0: every model posed on the CPU). */
static struct renderer *shown_with(struct content *s, const struct content_config *c,
				   uint32_t bones)
{
	struct renderer *r = renderer_new(&d->gl, NULL);

	assert_non_null(r);
	renderer_set_vertex_format(r, VERTEX_FLOAT32);
	renderer_set_bone_limit(r, bones);
	renderer_set_attribute_limit(r, attribute_limit);
	assert_int_equal(content_load(s, c, true), 0);
	assert_int_equal(content_prepare(s, c, SIZE, SIZE), 0);
	assert_int_equal(content_upload(s, r), 0);
	assert_int_equal(renderer_set_mode(r, c->mode, c->ortho), 0);
	return r;
}

static struct renderer *shown(struct content *s, const struct content_config *c)
{
	return shown_with(s, c, UINT32_MAX);
}

/* Pixels that differ, by how much at most, and how many by more than
 * 2/255 (the live pose's float matrices against the bake's doubles round
 * a shade by a level; a rasteriser without antialiasing, softpipe on
 * armhf, flips a silhouette pixel whose centre the edge grazes). */
static void compare(const struct image *a, const struct image *b, int *pixels, int *most, int *over)
{
	*pixels = *most = *over = 0;
	for (int i = 0; i < a->width * a->height; i++) {
		int diff = 0;

		for (int k = 0; k < 3; k++)
			diff = fmax(diff, abs(a->rgba[i * 4 + k] - b->rgba[i * 4 + k]));
		*pixels += diff > 0;
		*over += diff > 2;
		*most = diff > *most ? diff : *most;
	}
}

/* A clip time the clip's fit samples (a sixteenth of it): the still's fit
 * at that time is the live one's (gltf_fit.cc). gpu: skinned on the GPU
 * (where the model can be), else posed on the CPU. cached 1: the live
 * model must come from the prepared-mesh cache (its playback data read
 * back, no parse), 0: from the file, -1: either. */
static void live_frame_is_the_still(const char *path, char *animation, int sixteenths,
				    uint32_t bones, int cached)
{
	struct content_config lc = config(path, -1);
	struct content live, still;
	struct renderer *r;
	struct kiosk_anim *a = kiosk_anim_new();
	struct kiosk_anim_input in = {.running = true, .config = &lc};
	double t;
	uint64_t next;
	struct image fa, fb;
	int pixels, most, over;

	if (access(path, R_OK))
		return;
	lc.animation = animation;
	r = shown_with(&live, &lc, bones);
	assert_non_null(live.play);
	if (cached >= 0)
		assert_int_equal(live.cached != NULL, cached);
	if (!bones)
		assert_false(live.play_gpu);
	t = live.play->anim->clips[0].duration * sixteenths / 16;
	assert_true(kiosk_anim_step(a, &live, r, &in, T0, &next));
	assert_true(kiosk_anim_step(a, &live, r, &in, T0 + (uint64_t)llround(t * 1e9), &next));
	assert_true(fabs(kiosk_anim_time(a) - t) < 1e-6);
	draw(r, &live, &lc, &fa);

	struct content_config sc = config(path, t);
	struct renderer *rs;

	sc.animation = animation;
	rs = shown(&still, &sc);

	assert_null(still.play);
	draw(rs, &still, &sc, &fb);
	compare(&fa, &fb, &pixels, &most, &over);
	print_message("%s (%s%s) at %.3f s, %s: %d pixels differ, by %d at most, %d by more "
		      "than 2\n",
		      path, animation ? animation : "auto", live.cached ? ", from the cache" : "",
		      t,
		      !live.play_gpu	? "posed on the CPU"
		      : live.play_split ? "skinned on the GPU, its palette split"
					: "skinned on the GPU",
		      pixels, most, over);
	if (live.play->morph_targets)
		print_message("  its %u morph targets added in the vertex shader\n",
			      live.play->morph_targets);
	/* Every shade within 2/255 but a few silhouette pixels (0.1%): a
	 * wrong pose moves whole edges, hundreds of pixels (the weights left
	 * out: the cube off by 111 levels). */
	assert_true(over <= SIZE * SIZE / 1000);
	image_release(&fa);
	image_release(&fb);
	kiosk_anim_free(a);
	renderer_free(r);
	renderer_free(rs);
	content_release(&live);
	content_release(&still);
}

static void frames_equal_stills(void **state)
{
	/* The CPU path, one palette of two bones (a split into draws where
	 * the model has more), and one palette of all. The first round
	 * parses each model and writes its entry; the next ones play it
	 * from the cache. */
	static const uint32_t palettes[] = {0, 2, UINT32_MAX};

	(void)state;
	for (int i = 0; i < 3; i++) {
		live_frame_is_the_still(KHRONOS "RiggedSimple.gltf", NULL, 7, palettes[i], i > 0);
		live_frame_is_the_still(KHRONOS "SimpleMorph.gltf", NULL, 5, palettes[i], i > 0);
		live_frame_is_the_still(KHRONOS "BoxAnimated.gltf", NULL, 11, palettes[i], i > 0);
		/* Its two clips together, each on its own clock, as the still. */
		live_frame_is_the_still(KHRONOS "BoxAnimated.gltf", (char *)"all", 11, palettes[i],
					i > 0);
		live_frame_is_the_still("/usr/share/assimp/models/glTF2/glTF-Sample-Models/"
					"AnimatedMorphCube-glTF/AnimatedMorphCube.gltf",
					NULL, 6, palettes[i], i > 0);
	}
}

#define MORPH_CUBE                                                                                 \
	"/usr/share/assimp/models/glTF2/glTF-Sample-Models/AnimatedMorphCube-glTF/"                \
	"AnimatedMorphCube.gltf"

/* The program the renderer draws with: its active attributes, and
 * whether it reads morph weights. */
static void program_reads(const struct renderer *r, GLint *attributes, bool *morphs)
{
	struct renderer_stats st;

	renderer_get_stats(r, &st);
	assert_true(st.program != 0);
	d->gl.GetProgramiv(st.program, GL_ACTIVE_ATTRIBUTES, attributes);
	*morphs = d->gl.GetUniformLocation(st.program, "u_morph_weights") >= 0;
}

/* The model's live frame against its still with `limit` attributes, what
 * the journal said meanwhile into log. */
static void morph_frame_logged(const char *model, uint32_t limit, uint32_t bones, char *log,
			       size_t size)
{
	char path[] = "/tmp/mk-morph-log-XXXXXX";
	int fd = mkstemp(path), saved = dup(2);
	ssize_t got;

	assert_true(fd >= 0 && saved >= 0);
	attribute_limit = limit;
	fflush(stderr);
	dup2(fd, 2);
	live_frame_is_the_still(model, NULL, 6, bones, -1);
	fflush(stderr);
	dup2(saved, 2);
	close(saved);
	attribute_limit = 0;
	got = pread(fd, log, size - 1, 0);
	log[got > 0 ? got : 0] = '\0';
	close(fd);
	unlink(path);
}

/* AnimatedMorphCube's two targets move positions and normals: four
 * attributes, which a GPU of 9 leaves beside the position, normal, base
 * colour (a constant, at its location), bones and weights; the vertex
 * shader adds them and the arrays stay the parts' own. With GLES2's least
 * (8) they move on the CPU (skinned on the GPU still), and the journal
 * says why; the frames equal the still either way
 * (live_frame_is_the_still). A skinned model without targets builds no
 * morph program: its five attributes, no weights. */
static void morph_targets_on_the_gpu_or_cpu(void **state)
{
	(void)state;
	struct content_config c = config(MORPH_CUBE, -1);
	struct kiosk_anim_input in = {.running = true, .config = &c};
	struct kiosk_anim *a = kiosk_anim_new();
	struct content s;
	struct renderer *r;
	char log[8192];
	GLint attributes;
	bool morphs;
	uint64_t next;
	size_t n;
	float *own;

	if (access(MORPH_CUBE, R_OK)) {
		print_message("%s: not installed, left out\n", MORPH_CUBE);
		kiosk_anim_free(a);
		return;
	}
	attribute_limit = 9;
	r = shown(&s, &c);
	attribute_limit = 0;
	assert_true(s.play_gpu);
	assert_int_equal(s.play->morph_targets, 2);
	assert_true(s.play->morph_normals);
	/* Position, normal, base colour, bones, weights and the four. */
	program_reads(r, &attributes, &morphs);
	assert_int_equal(attributes, 9);
	assert_true(morphs);
	n = (size_t)s.mesh.vertex_count * 3;
	own = malloc(n * sizeof(float));
	assert_non_null(own);
	memcpy(own, s.mesh.positions, n * sizeof(float));
	assert_true(kiosk_anim_step(a, &s, r, &in, T0, &next));
	assert_true(kiosk_anim_step(a, &s, r, &in, T0 + 1500000000ull, &next));
	assert_memory_equal(own, s.mesh.positions, n * sizeof(float));
	free(own);
	kiosk_anim_free(a);
	/* The next model, skinned without targets, on the same renderer:
	 * programs without them (its five attributes, no weights), and the
	 * cube's arrays no longer bound. */
	struct content_config rc = config("tests/corpus/khronos/RiggedSimple.gltf", -1);
	struct content rigged;
	struct image frame;

	assert_int_equal(content_load(&rigged, &rc, true), 0);
	assert_int_equal(content_prepare(&rigged, &rc, SIZE, SIZE), 0);
	assert_int_equal(content_upload(&rigged, r), 0);
	assert_true(rigged.play_gpu);
	program_reads(r, &attributes, &morphs);
	assert_int_equal(attributes, 5);
	assert_false(morphs);
	draw(r, &rigged, &rc, &frame);
	assert_int_equal(d->gl.GetError(), GL_NO_ERROR);
	image_release(&frame);
	renderer_free(r);
	content_release(&s);
	content_release(&rigged);

	morph_frame_logged(MORPH_CUBE, 8, UINT32_MAX, log, sizeof(log));
	assert_non_null(strstr(log, "morph targets moved on the CPU each frame: the targets need "
				    "more vertex attributes than the GPU has left (4 attributes, "
				    "the program leaves 3"));
	assert_non_null(strstr(log, "skinned on the GPU"));
}

/* A sphere of two targets (tests/tools/gltf_morph.c) shown by one node
 * morphs on the GPU (its palette split into draws too); shown by two
 * nodes, each with its own weights, on the CPU (a program holds one
 * node's weights), and the journal says why; the frames equal their
 * stills. */
static void morphs_of_one_node_or_two(void **state)
{
	(void)state;
	char dir[] = "/tmp/mk-morph-XXXXXX", one[64], two[64], log[8192];
	struct mesh sphere;

	assert_non_null(mkdtemp(dir));
	snprintf(one, sizeof(one), "%s/one.glb", dir);
	snprintf(two, sizeof(two), "%s/two.glb", dir);
	assert_int_equal(mesh_uv_sphere(&sphere, 12, 8), 0);
	assert_int_equal(gltf_write_morph(one, &sphere, 1), 0);
	assert_int_equal(gltf_write_morph(two, &sphere, 2), 0);
	morph_frame_logged(one, 0, UINT32_MAX, log, sizeof(log));
	assert_non_null(strstr(log, "morph targets on the GPU: 2 of them with normals"));
	/* A palette of one bone: its draws cut, the deltas gathered with
	 * the vertices. */
	morph_frame_logged(one, 0, 1, log, sizeof(log));
	assert_non_null(strstr(log, "skinned on the GPU in 1 draws"));
	assert_non_null(strstr(log, "morph targets on the GPU: 2 of them with normals"));
	morph_frame_logged(two, 0, UINT32_MAX, log, sizeof(log));
	assert_non_null(strstr(log, "morph targets moved on the CPU each frame: parts of several "
				    "nodes have targets"));
	mesh_release(&sphere);
	unlink(one);
	unlink(two);
	rmdir(dir);
}

/* A capsule weighted over eight joints (JOINTS_1, tests/tools/gltf_joints.c)
 * plays live, posed on the CPU (the shader blends four), its frame the
 * still's; the journal says why, once. */
static void second_joint_set_on_the_cpu(void **state)
{
	(void)state;
	char dir[] = "/tmp/mk-joints8-XXXXXX", path[64], log[8192];
	const char *why = "posed on the CPU each frame: its vertices have more than four "
			  "joints (JOINTS_1)";
	struct mesh sphere;

	assert_non_null(mkdtemp(dir));
	snprintf(path, sizeof(path), "%s/capsule.glb", dir);
	assert_int_equal(mesh_uv_sphere(&sphere, 16, 12), 0);
	assert_int_equal(gltf_write_joints8(path, &sphere), 0);
	morph_frame_logged(path, 0, UINT32_MAX, log, sizeof(log));
	assert_non_null(strstr(log, why));
	assert_null(strstr(strstr(log, why) + 1, why));
	assert_null(strstr(log, "skinned on the GPU"));
	assert_null(strstr(log, "shows its first pose"));
	mesh_release(&sphere);
	unlink(path);
	rmdir(dir);
}

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
	    cmocka_unit_test(frames_equal_stills),
	    cmocka_unit_test(morph_targets_on_the_gpu_or_cpu),
	    cmocka_unit_test(morphs_of_one_node_or_two),
	    cmocka_unit_test(second_joint_set_on_the_cpu),
	    cmocka_unit_test(frames_at_the_rate),
	    cmocka_unit_test(step_keys_draw_at_their_rate),
	    cmocka_unit_test(next_animation_crossfades),
	    cmocka_unit_test(reload_goes_on),
	    cmocka_unit_test(all_is_a_step_of_the_cycle),
	    cmocka_unit_test(stops_play_their_clip),
	    cmocka_unit_test(still_models_cost_nothing),
	    cmocka_unit_test(a_clip_it_lacks_shows_still),
	};
	/* A cache of its own, empty: a model's first load is parsed (the
	 * next of the same settings come from the cache), and nothing is
	 * written where a user's or another test's cache is. */
	char cache[] = "/tmp/mk-anim-cache-XXXXXX", cmd[64];
	if (!mkdtemp(cache))
		return 1;
	setenv("XDG_CACHE_HOME", cache, 1);
	int failed = cmocka_run_group_tests_name("kiosk_anim", tests, open_display, NULL);
	snprintf(cmd, sizeof(cmd), "rm -rf %s", cache);
	if (system(cmd) != 0)
		fprintf(stderr, "could not remove %s\n", cache);
	return failed;
}
