/* The GLES2 renderer: knows shading, nothing of where the pixels go. */
#ifndef MK_RENDER_H
#define MK_RENDER_H

#include "gl.h"
#include "image.h"
#include "math3d.h"
#include "mesh.h"
#include "shading.h"

#include <stdbool.h>

struct view {
	struct quat orientation; /* of the model */
	bool ortho;		 /* orthographic: the unit sphere fills the short side */
	int rotation;		 /* of the panel: 0, 90, 180 or 270 degrees */
	float background[3];
};

struct renderer;

struct renderer *renderer_new(const struct gl *gl, const char *shader_dir);
void renderer_free(struct renderer *r);

int renderer_set_mesh(struct renderer *r, const struct mesh *m);
int renderer_set_matcap(struct renderer *r, const struct image *img);
/* Compiles the variant on first use; on failure the previous one stays. */
int renderer_set_mode(struct renderer *r, enum shading_mode mode, bool ortho);
void renderer_draw(struct renderer *r, const struct view *v, int width, int height);

/* The model-view and projection matrices the renderer uses (for tests). */
void render_matrices(const struct view *v, int width, int height, float modelview[16],
		     float projection[16]);

#endif
