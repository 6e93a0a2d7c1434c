/* What one output of several shows ([output.NAME], with [display]
 * outputs): the same view, the view turned 180 degrees about the vertical
 * (the back of a vitrine), turned by a fixed yaw, or its slice of a wall;
 * its own panel rotation, caption on or off, and background colour. A
 * plain function of the frame's view: the loop draws each output with
 * output_view_apply's copy. */
#ifndef MK_OUTPUT_VIEW_H
#define MK_OUTPUT_VIEW_H

#include "render/render.h"

#include <stdbool.h>

#define OUTPUT_VIEWS_MAX 4 /* as display.h's KMS_OUTPUTS_MAX */

/* [output.NAME] view, in the settings' order. */
enum output_look { OUTPUT_SAME, OUTPUT_MIRROR, OUTPUT_YAW, OUTPUT_SLICE };

struct output_view {
	char name[32]; /* the connector: HDMI-A-2 */
	enum output_look look;
	double yaw;	     /* degrees, turned about the vertical (OUTPUT_YAW) */
	int column, row;     /* its screen of [wall] columns x rows (OUTPUT_SLICE) */
	int rotation;	     /* the panel's, degrees; -1: [display] rotation */
	bool caption;	     /* the caption is drawn on it */
	bool has_background; /* background: a plain colour instead of [display]'s */
	float background[3];
};

struct output_views {
	int count;
	struct output_view items[OUTPUT_VIEWS_MAX];
};

extern const char *const output_look_names[]; /* NULL-terminated */

/* A section's defaults: the same view, [display] rotation, the caption. */
void output_view_defaults(struct output_view *o, const char *name);
/* The output named name, or NULL (it shows the frame's view as it is). */
const struct output_view *output_view_find(const struct output_views *s, const char *name);
/* v as output o shows it (o NULL: unchanged). */
void output_view_apply(const struct output_view *o, struct view *v);

#endif
