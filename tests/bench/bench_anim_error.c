/* What live playback's paths cost in error (issue 26), printed and never
 * asserted: a model's poses at eight times of its first clip, from the
 * parts live playback keeps, against the still the loader bakes at that
 * time in double (--time): the CPU path (anim_play_pose: double matrices,
 * float arrays), and the GPU path through the vertex shader's maths in C
 * (tests/oracle/anim_mirror.c: morph targets, then the bones' rows, in
 * binary32 as the vertex stage computes), its deltas as uploaded (float)
 * and as half floats would hold them (binary16; a model with targets).
 * One row a path: the
 * largest position error in the fitted model's radius (the fit puts the
 * whole clip in the unit sphere) and in pixels on a 1080-line screen the
 * model fills, and the largest normal error in degrees.
 *   bench_anim_error MODEL */
#include "oracle/anim_mirror.h"
#include "scene/gltf/gltf.h"
#include "util/log.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { CPU, GPU, GPU_HALF, PATHS };

struct error {
	double position, normal; /* radius units; degrees */
};

static void worst(struct error *e, const float *p, const float *n, const float *pp, const float *nn)
{
	double dot = 0, d = 0, c[3];

	for (int k = 0; k < 3; k++) {
		d = fmax(d, fabs((double)p[k] - pp[k]));
		dot += (double)n[k] * nn[k];
		c[k] = (double)n[(k + 1) % 3] * nn[(k + 2) % 3] -
		       (double)n[(k + 2) % 3] * nn[(k + 1) % 3];
	}
	e->position = fmax(e->position, d);
	/* The angle from its sine and cosine: exact for small ones. */
	e->normal =
	    fmax(e->normal, atan2(sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]), dot) * 180 / M_PI);
}

/* One time: each path's error at every vertex. */
static int at_time(const char *path, double t, struct error *e, bool *gpu, bool *morphs)
{
	struct anim_play *play = NULL;
	struct gltf_options o = {.pose = true, .time = t, .speed = 1, .play = &play};
	struct mesh still;
	struct anim_pose *pose;
	float *rows = NULL, *pos, *nrm, v[3], n[3], w[ANIM_PLAY_MORPH_MAX];
	const char *why;
	int ret = gltf_load_options(path, &o, &still);

	if (ret || !play)
		return ret ? ret : -EINVAL;
	pose = anim_pose_new(play->anim);
	pos = malloc((size_t)still.vertex_count * 12 + 4);
	nrm = malloc((size_t)still.vertex_count * 12 + 4);
	anim_pose_rest(play->anim, pose);
	anim_pose_apply(play->anim, &play->anim->clips[0], t, pose);
	anim_play_pose(play, pose, pos, nrm);
	for (uint32_t i = 0; i < still.vertex_count; i++)
		worst(&e[CPU], pos + i * 3, nrm + i * 3, still.positions + i * 3,
		      still.normals + i * 3);
	/* The GPU's maths with a palette and attributes of any size. */
	*gpu = anim_play_gpu_prepare(play, UINT32_MAX) == 0 &&
	       anim_play_morph_prepare(play, 1000, &why) == 0;
	if (*gpu)
		rows = malloc((size_t)play->bones * 48 + 4);
	*morphs = play->morph_targets > 0;
	for (int half = 0; rows && half < 2; half++) {
		anim_play_bones(play, pose, rows);
		anim_play_morph_weights(play, pose, w);
		for (uint32_t i = 0; i < still.vertex_count; i++) {
			anim_mirror_vertex(play, rows, w, i, half, v, n);
			worst(&e[GPU + half], v, n, still.positions + i * 3, still.normals + i * 3);
		}
	}
	free(rows);
	free(pos);
	free(nrm);
	anim_pose_free(pose);
	anim_play_free(play);
	mesh_release(&still);
	return 0;
}

int main(int argc, char **argv)
{
	static const char *names[PATHS] = {"CPU (double, float arrays)", "GPU (binary32)",
					   "GPU, deltas in binary16"};
	struct error e[PATHS] = {{0, 0}};
	struct anim_play *play = NULL;
	struct gltf_options o = {.pose = true, .speed = 1, .play = &play};
	struct mesh m;
	bool gpu = true, morphs = false;
	double duration;

	if (argc != 2) {
		fprintf(stderr, "usage: bench_anim_error MODEL\n");
		return 2;
	}
	log_set_level(LOG_WARN);
	if (gltf_load_options(argv[1], &o, &m) || !play)
		return 1;
	duration = play->anim->clips[0].duration;
	anim_play_free(play);
	mesh_release(&m);
	for (int i = 0; i < 8; i++)
		if (at_time(argv[1], duration * (i + 0.5) / 8, e, &gpu, &morphs))
			return 1;
	for (int p = 0; p < PATHS; p++)
		if (p == CPU || (gpu && (p == GPU || morphs)))
			printf("| %s | %s | %.2g | %.2g | %.2g |\n", strrchr(argv[1], '/') + 1,
			       names[p], e[p].position, e[p].position * 540, e[p].normal);
	return 0;
}
