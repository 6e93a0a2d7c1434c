/* A content's live playback (content.h, scene/anim_play.h): what the
 * preparation of the mesh leaves it. */
#include "content/content.h"
#include "util/log.h"

#include <errno.h>
#include <stdlib.h>

void content_play_check(struct content *s)
{
	/* The file's tangents, where no feature reads them, are not posed:
	 * they are left out, as the upload would leave them. */
	if (s->play && s->mesh.tangents && !material_needs_tangents(s->material.features)) {
		free(s->mesh.tangents);
		s->mesh.tangents = NULL;
	}
	if (!s->play || (s->play->vertex_count == s->mesh.vertex_count && !s->mesh.tangents))
		return;
	log_warn("%s: its animation does not play with this material's subdivision or tangents; "
		 "it shows its first pose",
		 s->model_path);
	anim_play_free(s->play);
	s->play = NULL;
}

int content_play_upload(struct content *s, struct renderer *r)
{
	uint32_t palette = renderer_bone_palette(r);
	int why = anim_play_gpu_prepare(s->play, palette);
	struct mesh own = s->mesh;

	s->play_gpu = why == 0;
	if (why == -ENOMEM)
		return why;
	if (!s->play_gpu) {
		log_info("%s: posed on the CPU each frame: %s", s->model_path,
			 why == -E2BIG ? "more bones than the GPU's palette holds"
				       : "a part's normals come from its posed triangles");
		return renderer_set_mesh_live(r, &s->mesh);
	}
	log_info("%s: skinned on the GPU: %u bones of a palette of %u", s->model_path,
		 s->play->bones, palette);
	/* The parts' own arrays; the bones pose them. */
	own.positions = s->play->positions;
	own.normals = s->play->normals;
	return renderer_set_mesh_skinned(r, &own, s->play->gpu_joints, s->play->gpu_weights,
					 s->play->bones);
}
