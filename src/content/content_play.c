/* A content's live playback (content.h, scene/anim_play.h): what the
 * preparation of the mesh leaves it. */
#include "content/content.h"
#include "util/log.h"

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
