/* The live kiosk's frames (src/app/kiosk_anim.h), drawn through OSMesa:
 * its frame at a playback time equals the --time still of that time
 * (RiggedSimple's skin, SimpleMorph's and AnimatedMorphCube's weights,
 * BoxAnimated's nodes, capsules of eight and twelve joints a vertex),
 * skinned on the GPU and posed on the CPU, morph targets on the GPU or the
 * CPU, and the journal says which and why. */
#include "gltf_joints.h"
#include "gltf_morph.h"

#include <math.h>
#include <string.h>
#include <unistd.h>

#include "anim_fixture.h"

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
		assert_ptr_equal(live.play_ops, &content_deform_cpu);
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
		      live.play_ops == &content_deform_cpu ? "posed on the CPU"
		      : live.play_split			   ? "skinned on the GPU, its palette split"
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
	assert_ptr_equal(s.play_ops, &content_deform_gpu);
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
	assert_ptr_equal(rigged.play_ops, &content_deform_gpu);
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

/* A capsule weighted over eight joints (JOINTS_1) and one over twelve
 * (JOINTS_2; tests/tools/gltf_joints.c) play live, posed on the CPU (the
 * shader blends four), each frame the still's; the journal says why,
 * once. */
static void joint_sets_on_the_cpu(void **state)
{
	(void)state;
	char dir[] = "/tmp/mk-joints8-XXXXXX", path[64], log[8192];
	const char *why = "posed on the CPU each frame: its vertices have more than four "
			  "joints (JOINTS_1)";
	struct mesh sphere;

	assert_non_null(mkdtemp(dir));
	assert_int_equal(mesh_uv_sphere(&sphere, 16, 12), 0);
	for (int sets = 2; sets <= 3; sets++) {
		snprintf(path, sizeof(path), "%s/capsule%d.glb", dir, 4 * sets);
		assert_int_equal(gltf_write_joints(path, &sphere, sets), 0);
		morph_frame_logged(path, 0, UINT32_MAX, log, sizeof(log));
		assert_non_null(strstr(log, why));
		assert_null(strstr(strstr(log, why) + 1, why));
		assert_null(strstr(log, "skinned on the GPU"));
		assert_null(strstr(log, "shows its first pose"));
		unlink(path);
	}
	mesh_release(&sphere);
	rmdir(dir);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(frames_equal_stills),
	    cmocka_unit_test(morph_targets_on_the_gpu_or_cpu),
	    cmocka_unit_test(morphs_of_one_node_or_two),
	    cmocka_unit_test(joint_sets_on_the_cpu),
	};

	return anim_tests_run("anim_frames", tests, sizeof(tests) / sizeof(tests[0]));
}
