/* glTF animation as plain data (cgltf style) and the pure maths that plays
 * it: keyframe samplers, loop modes, a clock that keeps its precision for
 * months, and node evaluation without recursion. Nothing here touches GL or
 * the file: the loader fills a struct mesh_anim beside the struct mesh, and
 * the renderer asks it for the pose at a time. */
#ifndef MK_ANIM_H
#define MK_ANIM_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

enum anim_interp { ANIM_STEP, ANIM_LINEAR, ANIM_CUBICSPLINE };
enum anim_path { ANIM_TRANSLATION, ANIM_ROTATION, ANIM_SCALE, ANIM_WEIGHTS };
enum anim_loop { ANIM_REPEAT, ANIM_ONCE, ANIM_PINGPONG };

/* One glTF sampler: key times (strictly increasing, seconds) and their
 * values, `width` floats a key (3 for translation and scale, 4 for a
 * rotation quaternion x y z w, the node's morph target count for
 * weights). CUBICSPLINE keys hold in-tangent, value, out-tangent. */
struct anim_sampler {
	float *input;
	float *output;
	size_t count;
	int width;
	enum anim_interp interp;
};

struct anim_channel {
	int node;
	enum anim_path path;
	int sampler;
};

struct anim_clip {
	char *name; /* NULL when the file gives none */
	struct anim_sampler *samplers;
	size_t sampler_count;
	struct anim_channel *channels;
	size_t channel_count;
	double duration; /* the last key time of all its samplers */
};

/* A node's local transform: translation, rotation (x y z w), scale. */
struct anim_trs {
	float t[3], r[4], s[3];
};

struct anim_node {
	int parent; /* -1 for a root */
	struct anim_trs rest;
	/* A node given by a matrix: the spec forbids animating it, so its
	 * matrix stands as it is. */
	bool has_matrix;
	float matrix[16];
	/* Its morph weights in a pose's weights array. */
	size_t weight_offset, weight_count;
};

struct mesh_anim {
	struct anim_node *nodes;
	size_t node_count;
	/* Node indices, every parent before its children (anim_order). */
	int *order;
	float *rest_weights; /* weight_total, the nodes' default morph weights */
	size_t weight_total;
	struct anim_clip *clips;
	size_t clip_count;
};

/* A pose: every node's local transform and morph weights. */
struct anim_pose {
	struct anim_trs *local;
	float *weights;
};

/* The value of sampler s at time t (seconds; before the first key: the
 * first value, after the last: the last), `width` floats into out. A
 * rotation interpolates by slerp the shorter way (LINEAR) or is
 * normalised (CUBICSPLINE). */
void anim_sampler_eval(const struct anim_sampler *s, bool rotation, double t, float *out);
/* NULL when s is well formed, else what is wrong with it (a static string). */
const char *anim_sampler_check(const struct anim_sampler *s);

/* Spherical interpolation of unit quaternions (x y z w), the shorter way
 * round: q and -q are the same rotation, and a key pair half a turn
 * apart in sign must not spin the long way. */
void anim_quat_slerp(const float a[4], const float b[4], double u, float out[4]);

/* The local time of a clip: integer nanoseconds of clip time, wrapped
 * once per loop, so a kiosk that runs for a year plays its clip as
 * smoothly as in the first minute (a float of seconds since start stops
 * moving after days; a double of seconds since start steps in coarser
 * and coarser ticks). Speed scales the wall clock; the fraction of a
 * nanosecond each step leaves is carried to the next. */
struct anim_clock {
	uint64_t duration_ns;
	uint64_t phase_ns; /* in [0, period): period is duration, twice that for pingpong */
	double carry;	   /* the fraction of a nanosecond not yet added */
	double speed;
	enum anim_loop loop;
};

void anim_clock_init(struct anim_clock *c, double duration, enum anim_loop loop, double speed);
void anim_clock_advance(struct anim_clock *c, uint64_t wall_ns);
/* From the start, `seconds` of wall time later (for --time). */
void anim_clock_seek(struct anim_clock *c, double seconds);
/* The clip time now, seconds in [0, duration]. */
double anim_clock_time(const struct anim_clock *c);
/* false once nothing will move: a clip of no length, or `once` ended. */
bool anim_clock_moving(const struct anim_clock *c);

/* Fills order[node_count] with the nodes parents first, by depth, without
 * recursion. false when the parents make a cycle or name a node that
 * does not exist. */
bool anim_order(const struct anim_node *nodes, size_t node_count, int *order);

struct anim_pose *anim_pose_new(const struct mesh_anim *a);
void anim_pose_free(struct anim_pose *p);
/* The rest pose, then a clip's channels at clip time t over it. */
void anim_pose_rest(const struct mesh_anim *a, struct anim_pose *p);
void anim_pose_apply(const struct mesh_anim *a, const struct anim_clip *clip, double t,
		     struct anim_pose *p);
/* p = p blended toward q by u (0: p, 1: q): the crossfade between clips. */
void anim_pose_blend(const struct mesh_anim *a, struct anim_pose *p, const struct anim_pose *q,
		     double u);
/* Every node's world matrix (column-major) from a pose, parents first. */
void anim_pose_world(const struct mesh_anim *a, const struct anim_pose *p, float (*world)[16]);
void anim_trs_matrix(const struct anim_trs *trs, float m[16]);

/* How long (clip seconds) a clip's pose holds from t on: 0 when a
 * sampler moves between its keys (LINEAR, CUBICSPLINE: it changes every
 * frame); with STEP keys alone, until the next key after t (backward,
 * pingpong's way back: until t passes below the key it holds), or the
 * clip's end (start), where the loop goes on. The live kiosk draws no
 * frame meanwhile. */
double anim_clip_hold(const struct anim_clip *c, double t, bool backward);

/* The clip a setting names: "auto" (the first), a name, or an index; -1
 * for "off", "all" or no clip; -2 when the name matches none. */
int anim_clip_find(const struct mesh_anim *a, const char *want);
void mesh_anim_free(struct mesh_anim *a);

#ifdef __cplusplus
}
#endif

#endif
