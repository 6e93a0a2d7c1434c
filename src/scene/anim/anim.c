/* Poses: a clip's channels over the rest pose, crossfades between poses,
 * and world matrices parents first, by a loop rather than recursion (a
 * hierarchy of any depth costs no stack). */
#include "scene/anim/anim.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Each node's depth, by walking up to the first node whose depth is
 * known and back down the path walked: every node is visited a bounded
 * number of times, so a chain of 100,000 costs a loop. false on a cycle
 * or a parent that does not exist. */
static bool node_depths(const struct anim_node *nodes, size_t node_count, size_t *depth,
			char *state, int *path)
{
	for (size_t i = 0; i < node_count; i++) {
		size_t len = 0;
		int p = (int)i;

		while (p >= 0 && state[p] != 2) {
			if ((size_t)p >= node_count || state[p] == 1)
				return false; // missing, or met again on this walk
			state[p] = 1;
			path[len++] = p;
			p = nodes[p].parent;
			if (p >= 0 && (size_t)p >= node_count)
				return false;
		}
		size_t d = p < 0 ? 0 : depth[p] + 1;

		while (len > 0) {
			int n = path[--len];

			depth[n] = d++;
			state[n] = 2;
		}
	}
	return true;
}

bool anim_order(const struct anim_node *nodes, size_t node_count, int *order)
{
	size_t n = node_count ? node_count : 1;
	size_t *depth = calloc(n, sizeof(*depth));
	size_t *count = calloc(n + 1, sizeof(*count));
	char *state = calloc(n, 1);
	int *path = calloc(n, sizeof(*path));
	bool ok =
	    depth && count && state && path && node_depths(nodes, node_count, depth, state, path);

	// Counting sort by depth: parents (shallower) first.
	for (size_t i = 0; ok && i < node_count; i++)
		count[depth[i] + 1]++;
	for (size_t d = 1; ok && d <= node_count; d++)
		count[d] += count[d - 1];
	for (size_t i = 0; ok && i < node_count; i++)
		order[count[depth[i]]++] = (int)i;
	free(depth);
	free(count);
	free(state);
	free(path);
	return ok;
}

struct anim_pose *anim_pose_new(const struct mesh_anim *a)
{
	struct anim_pose *p = calloc(1, sizeof(*p));

	if (!p)
		return NULL;
	p->local = calloc(a->node_count ? a->node_count : 1, sizeof(*p->local));
	p->weights = calloc(a->weight_total ? a->weight_total : 1, sizeof(*p->weights));
	if (!p->local || !p->weights) {
		anim_pose_free(p);
		return NULL;
	}
	anim_pose_rest(a, p);
	return p;
}

void anim_pose_free(struct anim_pose *p)
{
	if (!p)
		return;
	free(p->local);
	free(p->weights);
	free(p);
}

void anim_pose_rest(const struct mesh_anim *a, struct anim_pose *p)
{
	for (size_t i = 0; i < a->node_count; i++)
		p->local[i] = a->nodes[i].rest;
	if (a->weight_total)
		memcpy(p->weights, a->rest_weights, a->weight_total * sizeof(float));
}

void anim_pose_apply(const struct mesh_anim *a, const struct anim_clip *clip, double t,
		     struct anim_pose *p)
{
	for (size_t i = 0; i < clip->channel_count; i++) {
		const struct anim_channel *ch = &clip->channels[i];
		const struct anim_sampler *s = &clip->samplers[ch->sampler];
		const struct anim_node *n = &a->nodes[ch->node];
		struct anim_trs *l = &p->local[ch->node];

		// The loader checked each sampler's width against its path.
		switch (ch->path) {
		case ANIM_TRANSLATION:
			anim_sampler_eval(s, false, t, l->t);
			break;
		case ANIM_ROTATION:
			anim_sampler_eval(s, true, t, l->r);
			break;
		case ANIM_SCALE:
			anim_sampler_eval(s, false, t, l->s);
			break;
		case ANIM_WEIGHTS:
			if ((size_t)s->width == n->weight_count)
				anim_sampler_eval(s, false, t, p->weights + n->weight_offset);
			break;
		}
	}
}

void anim_pose_blend(const struct mesh_anim *a, struct anim_pose *p, const struct anim_pose *q,
		     double u)
{
	for (size_t i = 0; i < a->node_count; i++) {
		struct anim_trs *x = &p->local[i];
		const struct anim_trs *y = &q->local[i];

		for (int k = 0; k < 3; k++) {
			x->t[k] = (float)(x->t[k] + u * ((double)y->t[k] - x->t[k]));
			x->s[k] = (float)(x->s[k] + u * ((double)y->s[k] - x->s[k]));
		}
		anim_quat_slerp(x->r, y->r, u, x->r);
	}
	for (size_t i = 0; i < a->weight_total; i++)
		p->weights[i] =
		    (float)(p->weights[i] + u * ((double)q->weights[i] - p->weights[i]));
}

void anim_trs_matrix(const struct anim_trs *trs, float m[16])
{
	double x = trs->r[0], y = trs->r[1], z = trs->r[2], w = trs->r[3];
	double r[9] = {1 - 2 * (y * y + z * z), 2 * (x * y + w * z),	 2 * (x * z - w * y),
		       2 * (x * y - w * z),	1 - 2 * (x * x + z * z), 2 * (y * z + w * x),
		       2 * (x * z + w * y),	2 * (y * z - w * x),	 1 - 2 * (x * x + y * y)};

	for (int c = 0; c < 3; c++) {
		for (int row = 0; row < 3; row++)
			m[c * 4 + row] = (float)(r[c * 3 + row] * trs->s[c]);
		m[c * 4 + 3] = 0;
	}
	m[12] = trs->t[0];
	m[13] = trs->t[1];
	m[14] = trs->t[2];
	m[15] = 1;
}

static void mul(float out[16], const float a[16], const float b[16])
{
	float r[16];

	for (int c = 0; c < 4; c++)
		for (int row = 0; row < 4; row++) {
			double s = 0;

			for (int k = 0; k < 4; k++)
				s += (double)a[k * 4 + row] * b[c * 4 + k];
			r[c * 4 + row] = (float)s;
		}
	memcpy(out, r, sizeof(r));
}

void anim_pose_world(const struct mesh_anim *a, const struct anim_pose *p, float (*world)[16])
{
	for (size_t k = 0; k < a->node_count; k++) {
		size_t i = (size_t)a->order[k];
		const struct anim_node *n = &a->nodes[i];
		float local[16];

		if (n->has_matrix)
			memcpy(local, n->matrix, sizeof(local));
		else
			anim_trs_matrix(&p->local[i], local);
		if (n->parent < 0)
			memcpy(world[i], local, sizeof(local));
		else
			mul(world[i], world[n->parent], local);
	}
}

double anim_clip_hold(const struct anim_clip *c, double t, bool backward)
{
	double gap = backward ? t : c->duration - t;

	for (size_t i = 0; i < c->sampler_count; i++) {
		const struct anim_sampler *s = &c->samplers[i];
		size_t k = 0;

		if (s->count < 2)
			continue; /* one key: a constant */
		if (s->interp != ANIM_STEP)
			return 0;
		while (k < s->count && s->input[k] <= t)
			k++;
		/* Forward: the next key changes it; backward: leaving the key
		 * it holds (k - 1), unless that is the first. */
		if (!backward && k < s->count)
			gap = fmin(gap, s->input[k] - t);
		else if (backward && k >= 2)
			gap = fmin(gap, t - s->input[k - 1]);
	}
	return gap > 0 ? gap : 0;
}

int anim_clip_find(const struct mesh_anim *a, const char *want)
{
	if (!a || a->clip_count == 0 || !want || !strcmp(want, "off") || !strcmp(want, "all"))
		return -1;
	if (!*want || !strcmp(want, "auto"))
		return 0;
	for (size_t i = 0; i < a->clip_count; i++)
		if (a->clips[i].name && !strcmp(a->clips[i].name, want))
			return (int)i;
	char *end;
	long i = strtol(want, &end, 10);

	if (!*end && end != want && i >= 0 && (size_t)i < a->clip_count)
		return (int)i;
	return -2;
}

void mesh_anim_free(struct mesh_anim *a)
{
	if (!a)
		return;
	for (size_t c = 0; c < a->clip_count; c++) {
		struct anim_clip *clip = &a->clips[c];

		for (size_t s = 0; s < clip->sampler_count; s++) {
			free(clip->samplers[s].input);
			free(clip->samplers[s].output);
		}
		free(clip->samplers);
		free(clip->channels);
		free(clip->name);
	}
	free(a->clips);
	free(a->nodes);
	free(a->order);
	free(a->rest_weights);
	free(a);
}
