/* A content's live playback (content.h, scene/anim_play.h): what the
 * preparation of the mesh leaves it. */
#include "content/content.h"
#include "util/log.h"

void content_play_check(struct content *s)
{
	if (!s->play || (s->play->vertex_count == s->mesh.vertex_count && !s->mesh.tangents))
		return;
	log_warn("%s: its animation does not play with this material's subdivision or tangents; "
		 "it shows its first pose",
		 s->model_path);
	anim_play_free(s->play);
	s->play = NULL;
}
