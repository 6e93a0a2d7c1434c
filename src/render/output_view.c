#include "render/output_view.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

const char *const output_look_names[] = {"same", "mirror", "yaw", "slice", NULL};

void output_view_defaults(struct output_view *o, const char *name)
{
	memset(o, 0, sizeof(*o));
	snprintf(o->name, sizeof(o->name), "%s", name);
	o->rotation = -1;
	o->caption = true;
}

const struct output_view *output_view_find(const struct output_views *s, const char *name)
{
	for (int i = 0; name && i < s->count; i++)
		if (strcmp(s->items[i].name, name) == 0)
			return &s->items[i];
	return NULL;
}

/* The turn is about the world's vertical, after the model's own
 * orientation: a visitor walking round the case to its back sees the
 * model's back, upright, as the front's visitor sees its front. */
static void turn(struct view *v, double degrees)
{
	struct quat q = quat_from_axis_angle(0, 1, 0, degrees * M_PI / 180.0);

	v->orientation = quat_normalize(quat_multiply(q, v->orientation));
}

void output_view_apply(const struct output_view *o, struct view *v)
{
	if (!o)
		return;
	if (o->look == OUTPUT_MIRROR)
		turn(v, 180);
	else if (o->look == OUTPUT_YAW)
		turn(v, o->yaw);
	else if (o->look == OUTPUT_SLICE) {
		v->wall.column = o->column;
		v->wall.row = o->row;
	}
	if (o->rotation >= 0)
		v->rotation = o->rotation;
	if (o->has_background) {
		memcpy(v->background, o->background, sizeof(v->background));
		v->plain_background = true;
	}
}
