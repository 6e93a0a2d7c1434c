/* A content's hotspots: its settings' [hotspot.NAME] sections made the
 * renderer's (render/hotspot_gl.h) on the worker, their points moved
 * into the mesh's unit sphere by the loader's own fit, and handed to the
 * renderer with the model. */
#include "content/content.h"
#include "util/log.h"

#include <math.h>
#include <string.h>

/* The loader's centring and scale (mesh.fit); a mesh without one (the
 * built-in models, already in the unit sphere) is taken as it is. */
static void fit_of(const struct mesh *m, double centre[3], double *scale)
{
	bool known = m->fit[3] > 0 && isfinite(m->fit[3]);

	for (int k = 0; k < 3; k++)
		centre[k] = known ? m->fit[k] : 0;
	*scale = known ? m->fit[3] : 1;
}

void content_load_hotspots(struct content *s, const struct content_config *o)
{
	double centre[3], scale;
	int n = 0;

	fit_of(&s->mesh, centre, &scale);
	for (int i = 0; i < o->hotspots.count && n < CONTENT_HOTSPOTS; i++) {
		const struct hotspot *h = &o->hotspots.items[i];
		struct render_hotspot *out = &s->hotspots[n];

		if (!h->has_point) {
			log_warn(
			    "[hotspot.%s] node = %s: a node's hotspot is not drawn yet; give it "
			    "point = X Y Z",
			    h->name, h->node);
			continue;
		}
		memset(out, 0, sizeof(*out));
		for (int k = 0; k < 3; k++) {
			out->point[k] = (float)((h->point[k] - centre[k]) * scale);
			out->normal[k] = (float)h->normal[k];
		}
		out->has_normal = h->has_normal;
		out->badge = h->look == HOTSPOT_BADGE;
		out->number = i + 1;
		memcpy(out->color, h->color, sizeof(out->color));
		n++;
	}
	s->hotspot_count = n;
}
