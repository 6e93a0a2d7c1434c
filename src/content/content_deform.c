/* The backends of live playback (content.h struct content_deform_ops):
 * what each frame hands the renderer, on the path content_play_upload
 * chose for the model. The maths is the animation engine's
 * (scene/anim/anim_play.h): anim_play_joints makes the joint matrices
 * that anim_play_pose blends on the CPU and anim_play_bones packs for
 * the vertex shader. */
#include "content/content.h"

static void pose_cpu(struct content *s, struct renderer *r, const struct anim_pose *pose)
{
	anim_play_pose(s->play, pose, s->mesh.positions, s->mesh.normals);
	renderer_set_vertices(r, s->mesh.positions, s->mesh.normals);
}

/* One palette or a split's: the renderer hands each draw its bones. The
 * weights of targets not on the GPU are zeros, and unread. */
static void pose_gpu(struct content *s, struct renderer *r, const struct anim_pose *pose)
{
	float w[ANIM_PLAY_MORPH_MAX];

	anim_play_bones(s->play, pose, s->play->rows);
	renderer_set_bones(r, s->play->rows);
	anim_play_morph_weights(s->play, pose, w);
	renderer_set_morph_weights(r, w);
}

/* The targets move the parts' own arrays, which the bones then pose. */
static void pose_gpu_cpu_morphs(struct content *s, struct renderer *r, const struct anim_pose *pose)
{
	pose_gpu(s, r, pose);
	anim_play_morph(s->play, pose, s->mesh.positions, s->mesh.normals);
	renderer_set_vertices(r, s->mesh.positions, s->mesh.normals);
}

/* As above, the arrays gathered into the split's vertices. */
static void pose_gpu_split_cpu_morphs(struct content *s, struct renderer *r,
				      const struct anim_pose *pose)
{
	const struct anim_play_split *sp = s->play_split;

	pose_gpu(s, r, pose);
	anim_play_morph(s->play, pose, s->mesh.positions, s->mesh.normals);
	anim_play_split_gather(sp, s->mesh.positions, 3, sp->positions);
	anim_play_split_gather(sp, s->mesh.normals, 3, sp->normals);
	renderer_set_vertices(r, sp->positions, sp->normals);
}

const struct content_deform_ops content_deform_cpu = {"cpu", pose_cpu};
const struct content_deform_ops content_deform_gpu = {"gpu", pose_gpu};
const struct content_deform_ops content_deform_gpu_cpu_morphs = {"gpu, morphs on the cpu",
								 pose_gpu_cpu_morphs};
const struct content_deform_ops content_deform_gpu_split_cpu_morphs = {
    "gpu split, morphs on the cpu", pose_gpu_split_cpu_morphs};
