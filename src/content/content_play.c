/* A content's live playback (content.h, scene/anim_play.h): what the
 * preparation of the mesh leaves it. */
#include "content/content.h"
#include "util/log.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>

void content_play_check(struct content *s)
{
	/* The file's tangents, where no feature reads them, are not posed:
	 * they are left out, as the upload would leave them. */
	if (s->play && s->mesh.tangents && !material_needs_tangents(s->material.features)) {
		free(s->mesh.tangents);
		s->mesh.tangents = NULL;
	}
	if (s->play && s->play->vertex_count == s->mesh.vertex_count && !s->mesh.tangents) {
		log_info("%s: plays live at full detail: a simplified mesh would need its "
			 "parts' joints, weights and targets carried through each collapse",
			 s->model_path);
		return;
	}
	if (!s->play)
		return;
	log_warn("%s: its animation does not play with this material's subdivision or tangents; "
		 "it shows its first pose",
		 s->model_path);
	anim_play_free(s->play);
	s->play = NULL;
}

static void drop_split(struct content *s)
{
	if (s->play_split)
		anim_play_split_release(s->play_split);
	free(s->play_split);
	s->play_split = NULL;
}

void content_play_release(struct content *s)
{
	drop_split(s);
	anim_play_free(s->play);
	s->play = NULL;
	s->play_ops = NULL;
}

/* The morph targets on the GPU (none: NULL), their deltas gathered into
 * a split's vertices (*gathered, to free) when sp is set. */
static const struct skin_morphs *gpu_morphs(const struct anim_play *p,
					    const struct anim_play_split *sp,
					    struct skin_morphs *out, float **gathered)
{
	uint32_t n = anim_play_morph_attributes(p);

	*gathered = NULL;
	if (!p->morph_targets)
		return NULL;
	*out = (struct skin_morphs){p->morph_targets, p->morph_normals, p->gpu_morph};
	if (!sp)
		return out;
	*gathered = malloc((size_t)sp->vertex_count * 12 * n + 4);
	for (uint32_t a = 0; *gathered && a < n; a++)
		anim_play_split_gather(sp, p->gpu_morph + (size_t)a * p->vertex_count * 3, 3,
				       *gathered + (size_t)a * sp->vertex_count * 3);
	out->deltas = *gathered;
	return *gathered ? out : NULL;
}

/* The split's mesh: its own vertices (the parts' arrays, the UVs and
 * colours gathered), indices and ranges, the content's materials. */
static int upload_split(struct content *s, struct renderer *r, struct anim_play_split *sp)
{
	struct mesh m = s->mesh;
	float *uvs = m.uvs ? malloc((size_t)sp->vertex_count * 8 + 4) : NULL;
	float *colors = m.colors ? malloc((size_t)sp->vertex_count * 16 + 4) : NULL;
	struct skin_palettes pal = {s->play->bones, sp->range_count, sp->palette_first,
				    sp->palette_count, sp->bones};
	struct skin_morphs mo;
	float *deltas;
	const struct skin_morphs *morphs = gpu_morphs(s->play, sp, &mo, &deltas);
	int ret = (m.uvs && !uvs) || (m.colors && !colors) ? -ENOMEM : 0;

	if (s->play->morph_targets && !morphs)
		ret = -ENOMEM;

	anim_play_split_gather(sp, s->play->positions, 3, sp->positions);
	anim_play_split_gather(sp, s->play->normals, 3, sp->normals);
	if (uvs)
		anim_play_split_gather(sp, m.uvs, 2, uvs);
	if (colors)
		anim_play_split_gather(sp, m.colors, 4, colors);
	m.vertex_count = sp->vertex_count;
	m.index_count = sp->index_count;
	m.positions = sp->positions;
	m.normals = sp->normals;
	m.uvs = uvs;
	m.colors = colors;
	m.tangents = NULL;
	m.indices = sp->indices;
	m.range_count = sp->range_count;
	m.ranges = sp->ranges;
	/* The variants' table over the draws (their names are the mesh's). */
	m.variant_materials = sp->variant_materials;
	m.variant_ranges = sp->variant_materials ? sp->range_count : 0;
	if (!ret)
		ret = renderer_set_mesh_skinned(r, &m, sp->joints, sp->weights, sp->palette_max,
						&pal, morphs);
	free(deltas);
	free(uvs);
	free(colors);
	return ret;
}

/* More bones than one palette: cut into draws whose bones fit. skin:
 * the journal's words for it. */
static int split_palette(struct content *s, struct renderer *r, uint32_t palette, char *skin,
			 size_t size)
{
	int ret;

	if (!(s->play_split = calloc(1, sizeof(*s->play_split))))
		return -ENOMEM;
	ret = anim_play_split(s->play, &s->mesh, palette, s->play_split);
	if (!ret)
		ret = upload_split(s, r, s->play_split);
	if (!ret)
		snprintf(skin, size,
			 "skinned on the GPU in %u draws: %u bones, palettes of at most %u (the "
			 "GPU's holds %u)",
			 s->play_split->range_count, s->play->bones, s->play_split->palette_max,
			 palette);
	if (ret)
		drop_split(s);
	return ret;
}

/* One palette: the parts' own arrays, which the bones pose. */
static int one_palette(struct content *s, struct renderer *r, uint32_t palette, char *skin,
		       size_t size)
{
	struct mesh own = s->mesh;
	struct skin_morphs mo;
	float *none;

	snprintf(skin, size, "skinned on the GPU: %u bones of a palette of %u", s->play->bones,
		 palette);
	own.positions = s->play->positions;
	own.normals = s->play->normals;
	return renderer_set_mesh_skinned(r, &own, s->play->gpu_joints, s->play->gpu_weights,
					 s->play->bones, NULL,
					 gpu_morphs(s->play, NULL, &mo, &none));
}

/* On the GPU path: its morph targets there when the attributes the
 * program leaves hold them, else on the CPU (why says why). */
struct morph_place {
	uint32_t room, need;
	const char *why;
};

static int place_morphs(struct content *s, struct renderer *r, struct morph_place *m)
{
	m->room = renderer_morph_room(r);
	m->need = anim_play_morph_attributes(s->play);
	return anim_play_morph_prepare(s->play, m->room, &m->why) == -ENOMEM ? -ENOMEM : 0;
}

/* Where its morph targets move, and why, for the journal ("": none). */
static void say_morphs(const struct content *s, const struct morph_place *m, char *out, size_t size)
{
	*out = '\0';
	if (s->play->morph_targets)
		snprintf(out, size,
			 "; morph targets on the GPU: %u of them%s in %u vertex attributes of the "
			 "%u the program leaves",
			 s->play->morph_targets, s->play->morph_normals ? " with normals" : "",
			 m->need, m->room);
	else if (m->why)
		snprintf(out, size,
			 "; morph targets moved on the CPU each frame: %s (%u attributes, the "
			 "program leaves %u of the GPU's)",
			 m->why, m->need, m->room);
}

/* The GPU path's backend: where the morph targets move decides it. */
static const struct content_deform_ops *gpu_ops(const struct content *s)
{
	if (!s->play->morphs)
		return &content_deform_gpu;
	return s->play_split ? &content_deform_gpu_split_cpu_morphs
			     : &content_deform_gpu_cpu_morphs;
}

/* Every vertex on the CPU: the mesh's own arrays, replaced a frame. */
static int upload_cpu(struct content *s, struct renderer *r, int why)
{
	const char *none;

	s->play_ops = &content_deform_cpu;
	anim_play_morph_prepare(s->play, 0, &none); /* no arrays for the GPU */
	log_info("%s: animation '%s': posed on the CPU each frame: %s", s->model_path,
		 s->play_ops->name, anim_play_gpu_why(why));
	return renderer_set_mesh_live(r, &s->mesh);
}

/* The backend chosen once here (content_deform.c), and the journal told
 * which and why in one line. */
int content_play_upload(struct content *s, struct renderer *r)
{
	uint32_t palette = renderer_bone_palette(r);
	struct morph_place place = {0, 0, NULL};
	char skin[160], morphs[200];
	int ret, why = anim_play_gpu_prepare(s->play, palette);

	drop_split(s); /* uploaded again: decided again */
	s->play_ops = NULL;
	if ((why == 0 || why == -E2BIG) && place_morphs(s, r, &place))
		return -ENOMEM;
	if (why == -E2BIG && palette > 0)
		why = split_palette(s, r, palette, skin, sizeof(skin));
	else if (why == 0 && (ret = one_palette(s, r, palette, skin, sizeof(skin))))
		return ret;
	if (why == -ENOMEM)
		return why;
	if (why)
		return upload_cpu(s, r, why);
	s->play_ops = gpu_ops(s);
	say_morphs(s, &place, morphs, sizeof(morphs));
	log_info("%s: animation '%s': %s%s", s->model_path, s->play_ops->name, skin, morphs);
	return 0;
}
