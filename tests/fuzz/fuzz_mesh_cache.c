/* libFuzzer: the prepared-mesh cache's check (src/scene/mesh/mesh_cache.c) on
 * any bytes, as a damaged, truncated or planted entry would hand them
 * over: refused, or every index inside the arrays it describes. Each
 * input is checked as it is, and once more with its checksums made right
 * (mesh_cache_reseal), or the fuzzer would never get past them. An
 * entry's live playback section, accepted, is posed and prepared for the
 * GPU: every index it holds is used. */
#include "scene/anim/anim_play.h"
#include "scene/mesh/mesh_cache.h"
#include "util/log.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
	(void)argc;
	(void)argv;
	log_set_level((enum log_level)0);
	return 0;
}

/* The playback data it accepted, posed at a time of its first clip on
 * the CPU, then its bones and weights made for a palette of 4. */
static unsigned check_play(const void *data, size_t size)
{
	struct anim_play *p;
	struct anim_pose *pose;
	float *out;
	unsigned sum = 0;

	if (mesh_cache_parse_play(data, size, &p) || !p)
		return 0;
	pose = anim_pose_new(p->anim);
	out = malloc((size_t)p->vertex_count * 6 * sizeof(float));
	if (pose && out) {
		uint32_t bits;

		anim_pose_rest(p->anim, pose);
		if (p->anim->clip_count)
			anim_pose_apply(p->anim, &p->anim->clips[0], 0.5, pose);
		anim_play_pose(p, pose, out, out + (size_t)p->vertex_count * 3);
		memcpy(&bits, out, sizeof(bits)); /* used: not optimised away */
		sum += bits;
		anim_play_gpu_prepare(p, 4);
	}
	free(out);
	anim_pose_free(pose);
	anim_play_free(p);
	return sum;
}

static unsigned check(const void *data, size_t size)
{
	struct mesh_packed m;
	struct mesh mat;
	unsigned sum = 0;

	if (mesh_cache_parse(data, size, NULL, &m, &mat, NULL))
		return 0;
	/* Touch every byte of every array it accepted. */
	for (int a = 0; a < MESH_ARRAYS; a++) {
		size_t bytes = m.vertex_count * mesh_array_stride(m.format, (enum mesh_array)a);

		for (size_t i = 0; m.arrays[a] && i < bytes; i++)
			sum += ((const uint8_t *)m.arrays[a])[i];
	}
	for (uint32_t i = 0; i < m.index_count; i++)
		if (m.indices[i] >= m.vertex_count)
			abort();
	/* The ranges it accepted cover the indices, each material there. */
	for (uint32_t r = 0, at = 0; r < m.range_count; at += m.ranges[r++].index_count)
		if (m.ranges[r].first_index != at || m.ranges[r].material >= mat.material_count ||
		    (r + 1 == m.range_count && at + m.ranges[r].index_count != m.index_count))
			abort();
	mesh_release(&mat);
	return sum + check_play(data, size);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	/* Aligned as a mapping is: the arrays are read in place. */
	uint64_t *copy = malloc(size + 8);
	unsigned sum;

	if (!copy)
		return 0;
	memcpy(copy, data, size);
	sum = check(copy, size);
	mesh_cache_reseal(copy, size);
	sum += check(copy, size);
	free(copy);
	return (int)(sum & 0);
}
